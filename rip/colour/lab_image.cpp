// rip/colour/lab_image.cpp: OpenImageIO read of three channels and the resolution.
#include "rip/colour/lab_image.h"

#include <OpenImageIO/imageio.h>

namespace tp::rip {

Result<Image3f> read_image3f(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return fail(ErrorCode::kImage, path.string() + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.nchannels < 3) return fail(ErrorCode::kImage, path.string() + ": needs 3 channels");
  const float dpi = spec.get_float_attribute("XResolution", 0);
  const std::string unit = spec.get_string_attribute("ResolutionUnit", "in");
  if (!(dpi > 0)) return fail(ErrorCode::kImage, path.string() + ": no resolution (pHYs / XResolution)");
  Image3f r;
  r.width_px = spec.width;
  r.height_px = spec.height;
  r.px_per_mm = unit == "cm" ? dpi / 10.0 : dpi / 25.4;
  r.px.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, r.px.data()))
    return fail(ErrorCode::kImage, path.string() + ": " + in->geterror());
  return r;
}

}  // namespace tp::rip
