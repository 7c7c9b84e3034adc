// host/pipeline/internal/plan_codec.h: the files of a stored plan, written and read losslessly
// (every double round-trips bit for bit): the garment, the nested pieces and markers, the swath plan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "device/swath/swath.h"
#include "geometry/garment/garment.h"
#include "geometry/nesting/marker.h"
#include "geometry/nesting/nest_pieces.h"
#include "host/common/error.h"

namespace tp::host::internal {

/// `garment.plan`: the 3D vertices and every piece's chart (2D mesh, edge vertices, 3D indices).
[[nodiscard]] std::string garment_to_text(const geometry::Garment& garment, bool is_3d);
/// Parses garment_to_text's output. Fails (kPipeline) naming `where` and the line.
[[nodiscard]] Result<geometry::Garment> garment_from_text(const std::string& text, const std::string& where,
                                                          bool* is_3d);

/// `pieces.json`: what the marker stage nested (piece, name, cut outline, grain, rules).
[[nodiscard]] std::string pieces_to_json(const std::vector<geometry::NestItem>& items);

/// `marker.json`: the markers as nested, in their own frames, with what the search spent.
[[nodiscard]] std::string markers_to_json(const std::vector<geometry::Marker>& markers,
                                          const geometry::NestStats& stats);
/// Parses markers_to_json's output. Fails (kPipeline) naming `where` and the field.
[[nodiscard]] Result<std::vector<geometry::Marker>> markers_from_json(const std::string& text, const std::string& where);

/// One swath as planned: where it prints and a digest of its header and data.
struct PlannedSwath {
  std::uint32_t index = 0;
  std::int64_t first_row = 0;
  std::uint32_t rows = 0;
  std::uint16_t pass = 0;
  std::uint32_t feed_before_um = 0;
  std::uint64_t bytes = 0;
  std::string digest;  ///< InputHash of the header fields and the compressed data
};

/// Digest of a swath exactly as it would go to the printer.
[[nodiscard]] PlannedSwath plan_swath(const device::Swath& swath);

/// `swaths.json`: every swath of the job in index order.
[[nodiscard]] std::string swaths_to_json(const std::vector<PlannedSwath>& swaths);
[[nodiscard]] Result<std::vector<PlannedSwath>> swaths_from_json(const std::string& text, const std::string& where);

}  // namespace tp::host::internal
