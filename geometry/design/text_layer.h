// geometry/design/text_layer.h: a line of text shaped (HarfBuzz) and rendered (FreeType) into an
// image that a planar design layer projects onto the garment (personalised names and numbers).
#pragma once

#include <filesystem>
#include <string>

#include "geometry/common/error.h"
#include "geometry/common/image.h"

namespace tp::geometry {

/// Default font: DejaVu Sans Bold from Debian's fonts-dejavu-core.
inline constexpr const char* kDefaultTextFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

/// How a text layer looks. Lengths are mm on the garment.
struct TextStyle {
  std::filesystem::path font_file = kDefaultTextFont;
  double cap_height_mm = 40;  ///< height of a capital letter ("H") on the garment
  Rgba8 colour{0, 0, 0, 255};
  double outline_mm = 0;  ///< outline width around every glyph (0: none)
  Rgba8 outline_colour{255, 255, 255, 255};
  double px_per_mm = 10;  ///< image resolution (10 px/mm = 254 dpi)
};

/// The rendered text: an RGBA image cropped to its ink (plus a transparent border), and its size
/// in mm (the planar layer's width and height, so letters come out `cap_height_mm` tall). The
/// line's layout box (advance by ascender + descender) is centred on the layer's centre: the
/// image's centre lies `offset_right_mm` to the right of and `offset_up_mm` above that point.
struct TextImage {
  ImageRgba8 image;
  double width_mm = 0;
  double height_mm = 0;
  double offset_right_mm = 0;
  double offset_up_mm = 0;
  int glyphs = 0;  ///< glyphs placed by the shaper
};

/// Shapes `text` (UTF-8, one line) with the font and renders it. Deterministic: the same text,
/// font file and style give the same pixels. Fails with kInvalidArgument for empty text or a bad
/// style, and kIo / kParse naming the font file when it cannot be read as a font.
[[nodiscard]] Result<TextImage> render_text_image(const std::string& text, const TextStyle& style);

}  // namespace tp::geometry
