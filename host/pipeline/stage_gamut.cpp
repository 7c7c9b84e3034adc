// host/pipeline/stage_gamut.cpp: the report's gamut figures, from a soft proof of marker.png
// through the printer profile the job prints with.
#include <filesystem>

#include "host/pipeline/internal/gamut_report.h"
#include "host/pipeline/internal/output_files.h"
#include "host/pipeline/printer_model.h"
#include "rip/colour/ink_converter.h"
#include "rip/colour/proof_check.h"
#include "rip/colour/soft_proof.h"
#include "rip/image/image_io.h"

namespace tp::host::internal {

namespace fs = std::filesystem;

Status report_gamut(PipelineState& ps) {
  const PrintSpec& p = ps.job.print;
  fs::path profile;
  std::string source;
  if (p.calibration_profile) {
    profile = *p.calibration_profile;
    source = "calibration";
  } else if (p.icc_profile) {
    profile = *p.icc_profile;
    source = "print.icc_profile";
  } else {
    auto model = job_printer_model(ps.job);
    if (!model) return fail(model.error());
    std::vector<std::string> inks;
    for (const auto& ink : model->inks) inks.push_back(ink.name);
    if (inks == std::vector<std::string>{"cyan", "magenta", "yellow", "black"} &&
        fs::exists(rip::kDefaultCmykProfilePath)) {
      profile = rip::kDefaultCmykProfilePath;
      source = "default";
    }
  }
  auto& g = ps.report["gamut"];
  if (profile.empty()) {
    g = {{"reason",
          "no printer profile to proof against: the printer's inks are not CMYK and the job names none "
          "(print.calibration or print.icc_profile)"}};
    return {};
  }
  const fs::path marker = ps.options.out_dir / "marker.png";
  auto design = rip::read_image(marker);
  if (!design) return fail(ErrorCode::kPipeline, "gamut: " + design.error().message);
  geometry::ImageRgba8 proof, overlay;
  auto s = rip::soft_proof(*design, profile, proof, &overlay);
  if (!s) return fail(ErrorCode::kPipeline, "gamut: " + s.error().message);
  if (auto st =
          write_png_checked(ps.options.out_dir / "marker-proof.png", proof, rip::PngChannels::kRgba, p.preview_dpi);
      !st)
    return st;
  if (auto st =
          write_png_checked(ps.options.out_dir / "marker-gamut.png", overlay, rip::PngChannels::kRgba, p.preview_dpi);
      !st)
    return st;
  g = {{"profile", profile.string()},
       {"profile_source", source},
       {"design", "marker.png"},
       {"printed_pixels", s->printed_pixels},
       {"out_of_gamut_share", s->out_of_gamut_share},
       {"worst_de00", s->worst_de00},
       {"tolerance_de00", rip::kGamutTolerance_de00},
       {"files", {{"proof", "marker-proof.png"}, {"overlay", "marker-gamut.png"}}}};
  return {};
}

}  // namespace tp::host::internal
