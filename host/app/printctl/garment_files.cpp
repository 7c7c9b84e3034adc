// host/app/printctl/garment_files.cpp: OBJ and preview files of a sewn garment.
#include "host/app/printctl/garment_files.h"

#include <cstdio>
#include <fstream>

#include "geometry/garment/garment_obj.h"
#include "geometry/preview/render_preview.h"
#include "rip/image/image_io.h"

namespace tp::host::cli {
namespace {

std::string body_obj(const geometry::BodyMesh& body) {
  std::string out = "# " + body.name + ": body frame, mm (y up, z front, x wearer's left)\n";
  char buf[96];
  for (const auto& v : body.vertices_mm) {
    std::snprintf(buf, sizeof buf, "v %.3f %.3f %.3f\n", v.x, v.y, v.z);
    out += buf;
  }
  for (const auto& t : body.triangles) {
    std::snprintf(buf, sizeof buf, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += buf;
  }
  return out;
}

}  // namespace

std::string write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  return f ? std::string() : path.string() + ": cannot write";
}

std::string write_garment_files(const std::filesystem::path& dir, const std::string& stem,
                                const geometry::Pattern& pattern, const geometry::Garment& garment,
                                const geometry::BodyMesh& body, const std::string& body_stem) {
  if (auto err = write_text(dir / (stem + ".obj"), geometry::garment_to_obj(pattern, garment)); !err.empty()) return err;
  if (auto err = write_text(dir / (body_stem + ".obj"), body_obj(body)); !err.empty()) return err;
  for (auto view : {geometry::PreviewView::kFront, geometry::PreviewView::kSide, geometry::PreviewView::kBack}) {
    auto img = geometry::render_preview(garment, &body, view);
    auto path = dir / (stem + "_" + geometry::to_string(view) + ".png");
    if (auto s = rip::write_png(path, img, rip::PngChannels::kRgbOverWhite); !s) return s.error().what();
  }
  return {};
}

}  // namespace tp::host::cli
