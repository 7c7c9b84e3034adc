// geometry/design/textures.h: procedural source images made by project code (the paper's
// marbling, stripes, and a placement motif), for samples, tests and benchmarks.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/common/image.h"

namespace tp::geometry {

/// Marbled paper: veins of a palette swirled by periodic fractal noise. Tileable in both
/// directions (every term is periodic over the image), deterministic for a seed.
struct MarblingOptions {
  int width_px = 1024;
  int height_px = 1024;
  std::uint32_t seed = 1;
  int bands = 3;              ///< vein bands across the tile (an integer keeps it tileable)
  double turbulence = 2.2;    ///< swirl strength in radians
  std::vector<Rgba8> palette{{24, 44, 92, 255}, {32, 122, 140, 255}, {238, 228, 204, 255}, {196, 150, 64, 255}};
};
ImageRgba8 marbling(const MarblingOptions& options = {});

/// `count` stripes cycling through `colours` (vertical: across x), box-filtered edges; tileable.
ImageRgba8 stripes(int width_px, int height_px, int count, bool vertical, const std::vector<Rgba8>& colours);

/// A six-petal rosette on a transparent background, anti-aliased, for planar placement.
ImageRgba8 placement_motif(int size_px, Rgba8 petal = {176, 32, 72, 255}, Rgba8 centre = {250, 196, 40, 255});

}  // namespace tp::geometry
