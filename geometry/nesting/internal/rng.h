// geometry/nesting/internal/rng.h: a small seeded generator (xoshiro256**) so nesting runs repeat
// exactly for a given seed on every standard library.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace tp::geometry::nesting {

/// Deterministic pseudo-random generator; the same seed gives the same sequence everywhere.
class Rng {
 public:
  explicit Rng(std::uint64_t seed = 0) {
    // splitmix64 spreads any seed (0 included) over the four words of state.
    for (auto& s : state_) {
      seed += 0x9E3779B97F4A7C15ull;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
      s = z ^ (z >> 31);
    }
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi]; lo when the range is empty.
  double uniform(double lo, double hi) { return hi > lo ? lo + (hi - lo) * uniform() : lo; }
  /// Uniform integer in [0, n); 0 when n is 0.
  std::uint64_t below(std::uint64_t n) { return n ? next() % n : 0; }
  /// |N(0, sigma)| by the Box-Muller transform, for biased choices from sorted pools.
  double abs_normal(double sigma) {
    const double u1 = 1.0 - uniform(), u2 = uniform();
    return std::fabs(sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2));
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

}  // namespace tp::geometry::nesting
