// rip/screen/blue_noise.cpp: deterministic void-and-cluster generation of the blue-noise ranks.
#include "rip/screen/blue_noise.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace tp::rip {

namespace {

constexpr int kN = kBlueNoiseSize;
constexpr int kPixels = kN * kN;
constexpr int kRadius = 8;           ///< Gaussian truncated where it falls below 1e-6
constexpr double kSigmaPx = 1.5;
constexpr int kInitialOnesDivisor = 10;  ///< initial pattern: one pixel in ten set

/// Toroidal Gaussian energy field over the set pixels, in integer units (exactly reproducible).
class Energy {
 public:
  Energy() : field_(kPixels, 0) {
    for (int dy = -kRadius; dy <= kRadius; ++dy)
      for (int dx = -kRadius; dx <= kRadius; ++dx)
        kernel_[(dy + kRadius) * kSide + dx + kRadius] = static_cast<std::int32_t>(
            std::lround(std::exp(-(dx * dx + dy * dy) / (2 * kSigmaPx * kSigmaPx)) * (1 << 16)));
  }
  void add(int idx, int sign) {
    const int x0 = idx % kN, y0 = idx / kN;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
      const int y = (y0 + dy + kN) % kN;
      for (int dx = -kRadius; dx <= kRadius; ++dx) {
        const int x = (x0 + dx + kN) % kN;
        field_[y * kN + x] += sign * kernel_[(dy + kRadius) * kSide + dx + kRadius];
      }
    }
  }
  /// Set pixel with the highest energy (tightest cluster); lowest index wins ties.
  int tightest_cluster(const std::vector<std::uint8_t>& set) const {
    int best = -1;
    std::int32_t e = std::numeric_limits<std::int32_t>::min();
    for (int i = 0; i < kPixels; ++i)
      if (set[i] && field_[i] > e) e = field_[i], best = i;
    return best;
  }
  /// Unset pixel with the lowest energy (largest void); lowest index wins ties.
  int largest_void(const std::vector<std::uint8_t>& set) const {
    int best = -1;
    std::int32_t e = std::numeric_limits<std::int32_t>::max();
    for (int i = 0; i < kPixels; ++i)
      if (!set[i] && field_[i] < e) e = field_[i], best = i;
    return best;
  }

 private:
  static constexpr int kSide = 2 * kRadius + 1;
  std::int32_t kernel_[kSide * kSide];
  std::vector<std::int32_t> field_;
};

/// splitmix64: a tiny fixed PRNG so the seed pattern never depends on the standard library.
std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<std::uint16_t> generate() {
  std::vector<std::uint8_t> set(kPixels, 0);
  Energy energy;
  std::uint64_t seed = 0x7e871e5eedull;
  int ones = 0;
  while (ones < kPixels / kInitialOnesDivisor) {
    int idx = static_cast<int>(splitmix(seed) % kPixels);
    if (set[idx]) continue;
    set[idx] = 1;
    energy.add(idx, +1);
    ++ones;
  }
  // Relax the seed pattern: move the tightest cluster into the largest void until stable.
  for (int guard = 0; guard < kPixels; ++guard) {
    const int c = energy.tightest_cluster(set);
    set[c] = 0;
    energy.add(c, -1);
    const int v = energy.largest_void(set);
    set[v] = 1;
    energy.add(v, +1);
    if (v == c) break;
  }
  std::vector<std::uint16_t> rank(kPixels, 0);
  // Phase 1: ranks below the seed count, by removing tightest clusters from a copy.
  {
    std::vector<std::uint8_t> s = set;
    Energy e = energy;
    for (int r = ones - 1; r >= 0; --r) {
      const int c = e.tightest_cluster(s);
      s[c] = 0;
      e.add(c, -1);
      rank[c] = static_cast<std::uint16_t>(r);
    }
  }
  // Phases 2 and 3: fill the largest voids up to the full tile (with a fixed kernel sum, the
  // tightest cluster of minority zeros is the pixel of least energy among the zeros).
  for (int r = ones; r < kPixels; ++r) {
    const int v = energy.largest_void(set);
    set[v] = 1;
    energy.add(v, +1);
    rank[v] = static_cast<std::uint16_t>(r);
  }
  return rank;
}

}  // namespace

const std::vector<std::uint16_t>& blue_noise_ranks() {
  static const std::vector<std::uint16_t> ranks = generate();
  return ranks;
}

}  // namespace tp::rip
