// host/daemon/studio/studio_garment.h: one design-studio garment: the garment section a designer
// chose, sewn once by the pipeline's own stages, its mesh for the browser and its session folder
// (uploaded assets, previews), from which previews and job packages are made.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/common/cancel.h"
#include "host/common/error.h"
#include "host/job/job.h"
#include "host/job/package.h"
#include "host/pipeline/garment_files.h"
#include "host/pipeline/job_garment.h"

namespace tp::host {

/// Resolution of the studio's preview atlas (pieces at this dpi), and the mesh edge its garment
/// is sewn with: both chosen so a garment sews in seconds and a preview renders well under a
/// second on two cores.
inline constexpr double kStudioPreviewDpi = 16;
inline constexpr const char* kStudioMeshEdge = "25 mm";

/// zlib level of the preview atlas PNG: sent once and decoded at once, so packed fast, not small.
inline constexpr int kStudioPreviewPngLevel = 1;

/// The renderer's accuracy for previews: a quarter of a preview pixel, not of a print pixel, and
/// a layer weight (a planar image fading at the garment's sides) to 8 of 255, not half of one.
[[nodiscard]] geometry::RenderOptions studio_render_options(double dpi);

/// The garment a saved job prints on, sewn in the background from the moment the studio garment is
/// chosen (a save with strokes moves their points onto it, and sewing it takes tens of seconds).
struct PrintGarmentSewing {
  nlohmann::json section;  ///< the garment section it is sewn from (undraped)
  geometry::CancelToken cancel;
  std::mutex mu;
  std::condition_variable done_cv;
  bool done = false;
  bool orphaned = false;  ///< the studio garment is gone: its folder is removed when this ends
  Result<std::shared_ptr<const JobGarment>> result = fail(ErrorCode::kCancelled, "not sewn yet");
  double seconds = 0;
};

/// A sewn studio garment. The session folder is the package root: `assets/` holds the uploads
/// (pattern, body, images, textured OBJs) that the design's asset paths name.
struct StudioGarment {
  std::string id;
  std::filesystem::path dir;       ///< session folder (removed with the garment)
  nlohmann::json garment_section;  ///< job.json's "garment" object, asset paths relative to dir
  /// The garment section as the designer gave it, without the preview's mesh edge and drape: what
  /// a saved job prints with (the product's normal garment settings, unless the designer chose).
  nlohmann::json print_garment_section;
  JobGarment sewn;
  std::string obj;  ///< the garment mesh, UVs into the preview atlas (0..1), mm
  int atlas_width_px = 0, atlas_height_px = 0;
  double atlas_dpi = 0;
  std::vector<AtlasIsland> atlas_islands;  ///< the blank atlas's layout, which every preview repeats
  double sew_seconds = 0;
  /// The preview renderer's design-independent part (default finishing, preview options), made
  /// with the blank atlas and reused by every preview so a change rebuilds only the design's part.
  std::shared_ptr<const geometry::RendererBase> preview_base;
  /// The garment a saved job prints on, sewn (undraped) from `print_sewn_section` on the first save
  /// with strokes, so their points can be moved onto it; null until then.
  std::shared_ptr<const JobGarment> print_sewn;
  nlohmann::json print_sewn_section;
  /// The background sewing of the print garment (start_print_garment), or null.
  std::shared_ptr<PrintGarmentSewing> print_sewing;
  std::mutex mu;  ///< one preview or package at a time per garment

  /// Starts a preview: the one running (or waiting) before it is told to stop, as a newer design
  /// supersedes it. Returns the new preview's token.
  [[nodiscard]] geometry::CancelToken begin_preview();

  ~StudioGarment();

 private:
  std::mutex preview_mu_;
  geometry::CancelToken preview_cancel_;  ///< the latest preview's

 public:
  /// The garment's description for the API: id, pieces, mode, timings, URLs.
  [[nodiscard]] nlohmann::json describe() const;
};

/// The job.json text of a studio job: the garment's section (the preview's, or with `for_print`
/// the one a saved job prints with) with `rest` (design, finishing, marker, print, name; each
/// optional) merged in, and a default marker width.
[[nodiscard]] std::string studio_manifest(const StudioGarment& g, const nlohmann::json& rest, bool for_print = false);

/// Writes `manifest` as the session folder's job.json and parses it with the product's validator: the
/// errors are the same "job.json: /pointer: what" lines `printctl validate` prints.
[[nodiscard]] Result<Job> parse_studio_job(const StudioGarment& g, const std::string& manifest,
                                           const PackageLimits& limits);

/// Sews `garment_section` (asset paths relative to `dir`, which exists) at the studio's mesh edge,
/// undraped, and renders the blank atlas to map the mesh's UVs. Fails naming the field or stage.
[[nodiscard]] Result<std::unique_ptr<StudioGarment>> sew_studio_garment(std::string id,
                                                                        const std::filesystem::path& dir,
                                                                        nlohmann::json garment_section,
                                                                        const PackageLimits& limits,
                                                                        const geometry::CancelToken& cancel);

/// Starts sewing, on a thread of its own at a lower CPU priority (previews come first), the garment
/// a saved job prints on: `g.print_garment_section`, undraped. Does nothing when that is the
/// preview's garment, or when two such sewings run already (a save then sews it itself). The job
/// is parsed here, so call it with g.mu held or before g is shared.
void start_print_garment(StudioGarment& g, const PackageLimits& limits);

/// Joins every background sewing start_print_garment began (waiting for each to end). Their garments'
/// destructors cancel them, so destroy (or cancel) the garments first; printd calls this before
/// it exits, since those threads use the process's thread pool and logger.
void wait_for_print_sewings();

/// The print garment sewn from `section`: the background one (waited for) when it was started
/// for that section, else null (the caller sews it).
[[nodiscard]] Result<std::shared_ptr<const JobGarment>> await_print_garment(StudioGarment& g,
                                                                            const nlohmann::json& section);

}  // namespace tp::host
