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

/// Toroidal Gaussian energy field over the set pixels, in integer units (exactly reproducible),
/// with each row's tightest cluster and largest void kept up to date so a search scans 128 rows
/// instead of every pixel.
class Energy {
 public:
  Energy() : field_(kPixels, 0), set_(kPixels, 0) {
    for (int dy = -kRadius; dy <= kRadius; ++dy)
      for (int dx = -kRadius; dx <= kRadius; ++dx)
        kernel_[(dy + kRadius) * kSide + dx + kRadius] = static_cast<std::int32_t>(
            std::lround(std::exp(-(dx * dx + dy * dy) / (2 * kSigmaPx * kSigmaPx)) * (1 << 16)));
    for (int y = 0; y < kN; ++y) refresh_row(y);
  }
  bool is_set(int idx) const { return set_[idx] != 0; }

  /// Sets or clears pixel idx and updates the energy around it.
  void flip(int idx, bool on) {
    set_[idx] = on ? 1 : 0;
    const int sign = on ? 1 : -1, x0 = idx % kN, y0 = idx / kN;
    for (int dy = -kRadius; dy <= kRadius; ++dy) {
      const int y = (y0 + dy + kN) % kN;
      for (int dx = -kRadius; dx <= kRadius; ++dx) {
        const int x = (x0 + dx + kN) % kN;
        field_[y * kN + x] += sign * kernel_[(dy + kRadius) * kSide + dx + kRadius];
      }
      refresh_row(y);
    }
  }
  /// Set pixel with the highest energy (tightest cluster); lowest index wins ties.
  int tightest_cluster() const {
    int best = -1;
    std::int32_t e = std::numeric_limits<std::int32_t>::min();
    for (int y = 0; y < kN; ++y)
      if (row_cluster_[y] >= 0 && field_[row_cluster_[y]] > e) e = field_[row_cluster_[y]], best = row_cluster_[y];
    return best;
  }
  /// Unset pixel with the lowest energy (largest void); lowest index wins ties.
  int largest_void() const {
    int best = -1;
    std::int32_t e = std::numeric_limits<std::int32_t>::max();
    for (int y = 0; y < kN; ++y)
      if (row_void_[y] >= 0 && field_[row_void_[y]] < e) e = field_[row_void_[y]], best = row_void_[y];
    return best;
  }

 private:
  void refresh_row(int y) {
    int cluster = -1, gap = -1;
    std::int32_t hi = std::numeric_limits<std::int32_t>::min(), lo = std::numeric_limits<std::int32_t>::max();
    for (int i = y * kN; i < (y + 1) * kN; ++i) {
      if (set_[i]) {
        if (field_[i] > hi) hi = field_[i], cluster = i;
      } else if (field_[i] < lo) {
        lo = field_[i], gap = i;
      }
    }
    row_cluster_[y] = cluster;
    row_void_[y] = gap;
  }

  static constexpr int kSide = 2 * kRadius + 1;
  std::int32_t kernel_[kSide * kSide];
  std::vector<std::int32_t> field_;
  std::vector<std::uint8_t> set_;
  int row_cluster_[kN], row_void_[kN];
};

/// splitmix64: a tiny fixed PRNG so the seed pattern never depends on the standard library.
std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::vector<std::uint16_t> generate() {
  Energy energy;
  std::uint64_t seed = 0x7e871e5eedull;
  int ones = 0;
  while (ones < kPixels / kInitialOnesDivisor) {
    const int idx = static_cast<int>(splitmix(seed) % kPixels);
    if (energy.is_set(idx)) continue;
    energy.flip(idx, true);
    ++ones;
  }
  // Relax the seed pattern: move the tightest cluster into the largest void until stable.
  for (int guard = 0; guard < kPixels; ++guard) {
    const int c = energy.tightest_cluster();
    energy.flip(c, false);
    const int v = energy.largest_void();
    energy.flip(v, true);
    if (v == c) break;
  }
  std::vector<std::uint16_t> rank(kPixels, 0);
  // Phase 1: ranks below the seed count, by removing tightest clusters from a copy.
  {
    Energy e = energy;
    for (int r = ones - 1; r >= 0; --r) {
      const int c = e.tightest_cluster();
      e.flip(c, false);
      rank[c] = static_cast<std::uint16_t>(r);
    }
  }
  // Phases 2 and 3: fill the largest voids up to the full tile (with a fixed kernel sum, the
  // tightest cluster of minority zeros is the pixel of least energy among the zeros).
  for (int r = ones; r < kPixels; ++r) {
    const int v = energy.largest_void();
    energy.flip(v, true);
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
