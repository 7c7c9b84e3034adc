// rip/screen/blue_noise.h: the blue-noise threshold array (void-and-cluster) behind the fast screen.
#pragma once

#include <cstdint>
#include <vector>

namespace tp::rip {

/// Side of the square threshold tile, in pixels (5.4 mm at 600 dpi before it repeats).
inline constexpr int kBlueNoiseSize = 128;

/// A kBlueNoiseSize^2 tile (row-major) holding every rank 0 .. size^2-1 once, arranged so that the
/// pixels of rank < t form a blue-noise pattern for every t (Ulichney's void-and-cluster with a
/// Gaussian filter, sigma 1.5 px, on a torus so the tile repeats seamlessly).
///
/// Generated once per process from a fixed seed with integer energies, so it is identical on every
/// run and machine; the first call takes about 0.1-0.3 s, later calls return the cached tile.
const std::vector<std::uint16_t>& blue_noise_ranks();

}  // namespace tp::rip
