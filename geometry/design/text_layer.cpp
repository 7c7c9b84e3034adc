// geometry/design/text_layer.cpp: text shaped with HarfBuzz and rasterised with FreeType (fill
// and an optional stroked outline), composited into an RGBA image for a planar layer.
#include "geometry/design/text_layer.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_GLYPH_H
#include FT_STROKER_H
#include <hb-ft.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <system_error>
#include <vector>

namespace tp::geometry {

namespace {

// Transparent texels kept around the ink when the image is cropped to it.
constexpr int kInkBorderPx = 2;

// Owners of the FreeType and HarfBuzz objects, released in reverse order.
struct FtLibrary {
  FT_Library lib = nullptr;
  ~FtLibrary() {
    if (lib) FT_Done_FreeType(lib);
  }
};
struct FtFace {
  FT_Face face = nullptr;
  ~FtFace() {
    if (face) FT_Done_Face(face);
  }
};
struct HbFont {
  hb_font_t* font = nullptr;
  ~HbFont() {
    if (font) hb_font_destroy(font);
  }
};
struct HbBuffer {
  hb_buffer_t* buf = hb_buffer_create();
  ~HbBuffer() { hb_buffer_destroy(buf); }
};
struct FtGlyph {
  FT_Glyph glyph = nullptr;
  ~FtGlyph() {
    if (glyph) FT_Done_Glyph(glyph);
  }
};
struct FtStroker {
  FT_Stroker stroker = nullptr;
  ~FtStroker() {
    if (stroker) FT_Stroker_Done(stroker);
  }
};

// A coverage raster (0..1 per pixel) the glyph bitmaps are max-combined into.
struct Coverage {
  int w = 0, h = 0;
  std::vector<float> v;
  void add(const FT_Bitmap& bm, int left, int top) {
    for (unsigned r = 0; r < bm.rows; ++r) {
      const int y = top + static_cast<int>(r);
      if (y < 0 || y >= h) continue;
      for (unsigned c = 0; c < bm.width; ++c) {
        const int x = left + static_cast<int>(c);
        if (x < 0 || x >= w) continue;
        const float a = bm.buffer[r * static_cast<unsigned>(bm.pitch) + c] / 255.0f;
        float& d = v[static_cast<size_t>(y) * w + x];
        d = std::max(d, a);
      }
    }
  }
};

// Renders one glyph (filled, or its outside border `stroke_px` wide) at pen position (x, y) of the
// baseline, in 26.6 pixel units, into `cov` whose origin is (origin_x, origin_y) in the same frame.
std::string rasterise(FT_Face face, FT_Library lib, unsigned gid, double pen_x, double pen_y, double stroke_px,
                      Coverage& cov) {
  if (FT_Load_Glyph(face, gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
    return "cannot load glyph " + std::to_string(gid);
  FtGlyph g;
  if (FT_Get_Glyph(face->glyph, &g.glyph)) return "cannot copy glyph " + std::to_string(gid);
  if (stroke_px > 0) {
    FtStroker s;
    if (FT_Stroker_New(lib, &s.stroker)) return "cannot make a stroker";
    FT_Stroker_Set(s.stroker, static_cast<FT_Fixed>(std::lround(stroke_px * 64)), FT_STROKER_LINECAP_ROUND,
                   FT_STROKER_LINEJOIN_ROUND, 0);
    if (FT_Glyph_StrokeBorder(&g.glyph, s.stroker, 0, 1)) return "cannot stroke glyph " + std::to_string(gid);
  }
  // Sub-pixel pen position: the fractional part moves the outline before it is rasterised.
  const double fx = pen_x - std::floor(pen_x), fy = pen_y - std::floor(pen_y);
  FT_Vector delta{static_cast<FT_Pos>(std::lround(fx * 64)), static_cast<FT_Pos>(std::lround(-fy * 64))};
  if (FT_Glyph_To_Bitmap(&g.glyph, FT_RENDER_MODE_NORMAL, &delta, 1))
    return "cannot rasterise glyph " + std::to_string(gid);
  auto* bg = reinterpret_cast<FT_BitmapGlyph>(g.glyph);
  cov.add(bg->bitmap, static_cast<int>(std::floor(pen_x)) + bg->left, static_cast<int>(std::floor(pen_y)) - bg->top);
  return {};
}

std::uint8_t to_u8(double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); }

}  // namespace

Result<TextImage> render_text_image(const std::string& text, const TextStyle& style) {
  if (text.empty()) return fail(ErrorCode::kInvalidArgument, "text layer: the text is empty");
  if (!(style.cap_height_mm >= 1 && style.cap_height_mm <= 2000))
    return fail(ErrorCode::kInvalidArgument,
                "text layer: size " + std::to_string(style.cap_height_mm) + " mm outside 1..2000");
  if (!(style.outline_mm >= 0 && style.outline_mm <= style.cap_height_mm))
    return fail(ErrorCode::kInvalidArgument, "text layer: outline wider than the letters are tall");
  if (!(style.px_per_mm >= 1 && style.px_per_mm <= 50))
    return fail(ErrorCode::kInvalidArgument, "text layer: px_per_mm outside 1..50");
  const std::string font = style.font_file.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(style.font_file, ec)) return fail(ErrorCode::kIo, font + ": no such font file");

  FtLibrary lib;
  if (FT_Init_FreeType(&lib.lib)) return fail(ErrorCode::kIo, "text layer: FreeType did not start");
  FtFace face;
  if (FT_New_Face(lib.lib, font.c_str(), 0, &face.face))
    return fail(ErrorCode::kParse, font + ": not a font FreeType reads");
  if (!FT_IS_SCALABLE(face.face)) return fail(ErrorCode::kParse, font + ": not a scalable (outline) font");

  // The em size that makes a capital H cap_height_mm tall.
  const unsigned h_gid = FT_Get_Char_Index(face.face, 'H');
  double cap_em = 0.7;  // of the em, when the font has no H
  if (h_gid != 0 && !FT_Set_Char_Size(face.face, 0, 1000 * 64, 72, 72) &&
      !FT_Load_Glyph(face.face, h_gid, FT_LOAD_NO_HINTING | FT_LOAD_NO_SCALE))
    cap_em = static_cast<double>(face.face->glyph->metrics.height) / face.face->units_per_EM;
  const double em_px = style.cap_height_mm * style.px_per_mm / cap_em;
  if (FT_Set_Char_Size(face.face, 0, static_cast<FT_F26Dot6>(std::lround(em_px * 64)), 72, 72))
    return fail(ErrorCode::kParse, font + ": cannot scale to " + std::to_string(em_px) + " px");

  HbFont hb;
  hb.font = hb_ft_font_create_referenced(face.face);
  hb_ft_font_set_load_flags(hb.font, FT_LOAD_NO_HINTING);
  HbBuffer buf;
  hb_buffer_add_utf8(buf.buf, text.c_str(), static_cast<int>(text.size()), 0, -1);
  hb_buffer_guess_segment_properties(buf.buf);
  hb_shape(hb.font, buf.buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf.buf, &n);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf.buf, &n);
  if (n == 0) return fail(ErrorCode::kInvalidArgument, "text layer: '" + text + "' shapes to no glyphs");

  double advance_px = 0;
  for (unsigned i = 0; i < n; ++i) advance_px += pos[i].x_advance / 64.0;
  const double stroke_px = style.outline_mm * style.px_per_mm;
  const double ascender_px = face.face->size->metrics.ascender / 64.0;
  const double descender_px = -face.face->size->metrics.descender / 64.0;
  const double pad = std::ceil(stroke_px + 2);
  Coverage fill, outline;
  fill.w = outline.w = static_cast<int>(std::ceil(advance_px + 2 * pad));
  fill.h = outline.h = static_cast<int>(std::ceil(ascender_px + descender_px + 2 * pad));
  fill.v.assign(static_cast<size_t>(fill.w) * fill.h, 0.0f);
  if (stroke_px > 0) outline.v.assign(fill.v.size(), 0.0f);

  double pen_x = pad, pen_y = pad + ascender_px;
  for (unsigned i = 0; i < n; ++i) {
    const double gx = pen_x + pos[i].x_offset / 64.0, gy = pen_y - pos[i].y_offset / 64.0;
    if (auto e = rasterise(face.face, lib.lib, info[i].codepoint, gx, gy, 0, fill); !e.empty())
      return fail(ErrorCode::kParse, font + ": " + e);
    if (stroke_px > 0)
      if (auto e = rasterise(face.face, lib.lib, info[i].codepoint, gx, gy, stroke_px, outline); !e.empty())
        return fail(ErrorCode::kParse, font + ": " + e);
    pen_x += pos[i].x_advance / 64.0;
    pen_y -= pos[i].y_advance / 64.0;
  }

  // Fill over outline over nothing (straight alpha out).
  TextImage out;
  out.glyphs = static_cast<int>(n);
  out.image.width_px = fill.w;
  out.image.height_px = fill.h;
  out.image.pixels.resize(fill.v.size());
  out.image.source = "text:" + text;
  const Rgba8 fc = style.colour, oc = style.outline_colour;
  for (size_t k = 0; k < fill.v.size(); ++k) {
    const double af = fill.v[k] * fc.a / 255.0;
    const double ao = (stroke_px > 0 ? outline.v[k] : 0.0f) * oc.a / 255.0;
    const double a = af + ao * (1 - af);
    if (a <= 0) continue;
    auto ch = [&](std::uint8_t f, std::uint8_t o) { return to_u8((f * af + o * ao * (1 - af)) / a); };
    out.image.pixels[k] = {ch(fc.r, oc.r), ch(fc.g, oc.g), ch(fc.b, oc.b), to_u8(255 * a)};
  }
  // Only the ink's box (and a border of transparent texels for the filter) is kept: the layout
  // box's empty rows and bearings would cost memory in every copy's renderer for nothing.
  int x0 = fill.w, x1 = -1, y0 = fill.h, y1 = -1;
  for (int y = 0; y < fill.h; ++y)
    for (int x = 0; x < fill.w; ++x)
      if (out.image.pixels[static_cast<size_t>(y) * fill.w + x].a > 0)
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (x1 >= x0) {
    x0 = std::max(0, x0 - kInkBorderPx), y0 = std::max(0, y0 - kInkBorderPx);
    x1 = std::min(fill.w - 1, x1 + kInkBorderPx), y1 = std::min(fill.h - 1, y1 + kInkBorderPx);
    ImageRgba8 crop;
    crop.width_px = x1 - x0 + 1;
    crop.height_px = y1 - y0 + 1;
    crop.source = out.image.source;
    crop.pixels.reserve(static_cast<size_t>(crop.width_px) * crop.height_px);
    for (int y = y0; y <= y1; ++y) {
      const auto row = out.image.pixels.begin() + static_cast<std::ptrdiff_t>(y) * fill.w;
      crop.pixels.insert(crop.pixels.end(), row + x0, row + x1 + 1);
    }
    out.offset_right_mm = ((x0 + x1 + 1) / 2.0 - fill.w / 2.0) / style.px_per_mm;
    out.offset_up_mm = (fill.h / 2.0 - (y0 + y1 + 1) / 2.0) / style.px_per_mm;
    out.image = std::move(crop);
  }
  out.width_mm = out.image.width_px / style.px_per_mm;
  out.height_mm = out.image.height_px / style.px_per_mm;
  return out;
}

}  // namespace tp::geometry
