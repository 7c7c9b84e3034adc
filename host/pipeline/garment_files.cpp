// host/pipeline/garment_files.cpp: OBJ and preview files of a sewn garment.
#include "host/pipeline/garment_files.h"

#include <cstdio>
#include <fstream>

#include "geometry/garment/garment_obj.h"
#include "geometry/preview/render_preview.h"
#include "host/common/atomic_file.h"
#include "host/pipeline/internal/output_files.h"

namespace tp::host {
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

Status write_text_file(const std::filesystem::path& path, const std::string& text) {
  return write_file_atomic(path, text);
}

Result<std::vector<std::string>> write_garment_previews(const std::filesystem::path& dir, const std::string& prefix,
                                                        const geometry::Garment& garment,
                                                        const geometry::BodyMesh* body, rip::PngChannels channels) {
  std::vector<std::string> names;
  for (auto view : {geometry::PreviewView::kFront, geometry::PreviewView::kSide, geometry::PreviewView::kBack}) {
    const std::string name = prefix + geometry::to_string(view) + ".png";
    if (auto st = internal::write_png_checked(dir / name, geometry::render_preview(garment, body, view), channels); !st)
      return fail(st.error());
    names.push_back(name);
  }
  return names;
}

Status write_garment_files(const std::filesystem::path& dir, const std::string& stem, const geometry::Pattern& pattern,
                           const geometry::Garment& garment, const geometry::BodyMesh& body,
                           const std::string& body_stem) {
  if (auto st = write_text_file(dir / (stem + ".obj"), geometry::garment_to_obj(pattern, garment)); !st) return st;
  if (auto st = write_text_file(dir / (body_stem + ".obj"), body_obj(body)); !st) return st;
  auto previews = write_garment_previews(dir, stem + "_", garment, &body, rip::PngChannels::kRgbOverWhite);
  if (!previews) return fail(previews.error());
  return {};
}

}  // namespace tp::host
