// host/pipeline/order_previews.cpp: an order's garment wearing its print, one size at a time on
// that size's own body. The order's merged garment holds every copy side by side (800 mm apart),
// while a job has one body, the base size's: rendered as one, the first copy (size S) sat inside
// size M's body and the others beside it with none. So each size's first copy is cut out of the
// merged garment and moved back onto its own body.
#include <algorithm>
#include <filesystem>

#include "geometry/garment/flat_pieces.h"
#include "host/pipeline/garment_files.h"
#include "host/pipeline/internal/order_run.h"

namespace tp::host::internal {

geometry::Garment order_copy_garment(const geometry::Garment& merged, const OrderCopyRun& c) {
  const int end = c.first_piece + static_cast<int>(c.piece_names.size());
  std::vector<int> drop;
  for (size_t p = 0; p < merged.pieces.size(); ++p) {
    const int piece = merged.pieces[p].piece;
    if (piece < c.first_piece || piece >= end) drop.push_back(static_cast<int>(p));
  }
  geometry::Garment g = geometry::garment_without(merged, drop);
  for (geometry::Vec3& v : g.vertices_mm) v.x -= c.x_offset_mm;
  return g;
}

Result<std::vector<std::string>> write_order_print_previews(PipelineState& ps, const geometry::Garment& worn,
                                                            double dpi) {
  const OrderRun& run = *ps.order;
  std::vector<std::string> base_names;
  nlohmann::json& sizes = ps.report["sizes"];
  for (size_t si = 0; si < run.sizes.size(); ++si) {
    const OrderSizeRun& s = *run.sizes[si];
    const auto first = std::find_if(run.copies.begin(), run.copies.end(), [&](const auto& c) { return c->size == si; });
    if (first == run.copies.end()) continue;
    const geometry::Garment copy = order_copy_garment(worn, **first);
    const geometry::BodyMesh* body = s.ps && s.ps->body ? &s.ps->body->mesh() : nullptr;
    const std::filesystem::path dir = ps.options.out_dir / "sizes" / s.stem;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    auto names = write_garment_print_previews(dir, "garment-print-", copy, body, *ps.renderer, dpi);
    if (!names) return fail(names.error().with_context("order size '" + s.spec.size + "' print previews"));
    nlohmann::json files = nlohmann::json::array();
    for (const std::string& n : *names) files.push_back("sizes/" + s.stem + "/" + n);
    if (sizes.is_array() && si < sizes.size()) sizes[si]["print_previews"] = files;
    if (si != run.base) continue;
    // The job's own previews: the base size (the one the design was made on) on its body.
    for (const std::string& n : *names) {
      std::filesystem::copy_file(dir / n, ps.options.out_dir / n, std::filesystem::copy_options::overwrite_existing,
                                 ec);
      if (ec) return fail(ErrorCode::kIo, (ps.options.out_dir / n).string() + ": cannot write: " + ec.message());
      base_names.push_back(n);
    }
  }
  return base_names;
}

}  // namespace tp::host::internal
