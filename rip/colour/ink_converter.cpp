// rip/colour/ink_converter.cpp: builds the sRGB-to-ink table with lcms2 and interpolates it per pixel.
#include "rip/colour/ink_converter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include <lcms2.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/fmt/ranges.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/common/thread_pool.h"
#include "rip/colour/internal/lcms_handles.h"
#include "rip/colour/multi_ink_profile.h"
#include "rip/colour/profile_inverse.h"
#include "rip/common/internal/log.h"
#include "rip/common/memory.h"

namespace tp::rip {

namespace {

constexpr int kMaxInks = 15;          ///< lcms2 handles up to 15 colourants
constexpr int kMinGrid = 9, kMaxGrid = 65;
constexpr int kFracOne = 256;         ///< interpolation weights sum to this
constexpr int kNodeScale = 128;       ///< node values are 8-bit ink amounts times this (fits int16)
constexpr int kLane = 4;              ///< inks per 64-bit group of int16 node values

/// Entries of the direct table: every 8-bit sRGB colour.
constexpr size_t kDirectEntries = size_t{1} << 24;

/// Where one 8-bit input value falls on a grid axis.
struct AxisStep {
  std::uint32_t offset;  ///< node index along this axis times the axis stride (in table entries)
  std::uint32_t frac;    ///< 0..kFracOne toward the next node
};

cmsUInt32Number lcms_intent(RenderingIntent i) {
  switch (i) {
    case RenderingIntent::kPerceptual: return INTENT_PERCEPTUAL;
    case RenderingIntent::kRelativeColorimetric: return INTENT_RELATIVE_COLORIMETRIC;
    case RenderingIntent::kSaturation: return INTENT_SATURATION;
    case RenderingIntent::kAbsoluteColorimetric: return INTENT_ABSOLUTE_COLORIMETRIC;
  }
  return INTENT_PERCEPTUAL;
}

bool is_black(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name == "black" || name == "k";
}

}  // namespace

struct InkConverter::Table {
  int channels = 0;
  int grid = 0;
  int limit_8bit = 0;
  std::vector<std::string> names;
  int lanes = 0;                     ///< channels rounded up to kLane (node stride in int16)
  std::vector<std::int16_t> nodes;   ///< grid^3 * lanes, r slowest, ink fastest, padding inks zero
  /// The tetrahedron of each fraction order, indexed by (fr>=fg) | (fg>=fb)<<1 | (fr>=fb)<<2.
  struct Tetra {
    std::uint32_t d1, d2;    ///< offsets of the 2nd and 3rd corners (the 4th is the far corner)
  };
  std::array<Tetra, 8> tetra{};
  std::array<AxisStep, 256> axis_r{}, axis_g{}, axis_b{};
  std::uint32_t stride_r = 0, stride_g = 0, stride_b = 0;
  /// Up to four inks: every 8-bit sRGB colour's interpolated inks, packed one per byte (empty
  /// unless InkConverterSettings::direct_table). Colours are stored in 4x4x4 blocks, at
  /// direct_r[r] + direct_g[g] + direct_b[b], so that the nearby colours of a smooth image share
  /// cache lines and pages.
  /// 2^24 packed entries in memory of their own, backed by huge pages where the kernel allows: a
  /// pixel's lookup is one load, and neighbouring colours share pages.
  HugePageBlock direct;
  std::array<std::uint32_t, 256> direct_r{}, direct_g{}, direct_b{};
  // Kept for convert_exact: the same separation at full precision.
  lcms::Profile profile;
  lcms::Transform exact;  ///< sRGB double -> inks double (0..1), unoptimised
  std::unique_ptr<RgbProfileInverse> calibration;  ///< sRGB ahead of `exact` (a calibration set)
  std::vector<ToneCurve> curves;
  std::vector<bool> black;
  /// Device-value printing: per ink, the sRGB channel (0..2) that drives it directly, or -1.
  std::vector<int> device_channel;
  bool device_mode = false;
  double limit_fraction = 0;  ///< sum of ink fractions allowed at nodes (includes rounding margin)

  /// Tetrahedral interpolation: the cube splits into six tetrahedra by the order of the three
  /// fractions; the colour is a convex combination of one tetrahedron's corners (c0, c0 + d1,
  /// c0 + d2, the far corner) with weights w. The tetrahedron comes from a table, not branches:
  /// photographic input would mispredict them.
  struct Corners {
    const std::int16_t* c0;
    std::uint32_t d1, d2;
    std::uint32_t w[4];
  };
  Corners corners(std::uint8_t r, std::uint8_t g, std::uint8_t b) const {
    const AxisStep ar = axis_r[r], ag = axis_g[g], ab = axis_b[b];
    const std::uint32_t fr = ar.frac, fg = ag.frac, fb = ab.frac;
    const Tetra& tt = tetra[(fr >= fg) | ((fg >= fb) << 1) | ((fr >= fb) << 2)];
    // Largest, middle and smallest fraction without indexing.
    const std::uint32_t f1 = std::max(fr, std::max(fg, fb)), f3 = std::min(fr, std::min(fg, fb));
    const std::uint32_t f2 = fr + fg + fb - f1 - f3;
    return {nodes.data() + ar.offset + ag.offset + ab.offset, tt.d1, tt.d2, {kFracOne - f1, f1 - f2, f2 - f3, f3}};
  }

#if defined(__SSE2__)
  /// Inks lane..lane + 3 of the interpolation, packed one per byte.
  std::uint32_t interpolate_lanes(const Corners& k, int lane) const {
    const std::int16_t* c0 = k.c0 + lane;
    // madd multiplies (corner, weight) int16 pairs and adds each pair.
    const __m128i wa = _mm_set1_epi32(static_cast<int>(k.w[0] | (k.w[1] << 16)));
    const __m128i wb = _mm_set1_epi32(static_cast<int>(k.w[2] | (k.w[3] << 16)));
    const __m128i a0 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(c0));
    const __m128i a1 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(c0 + k.d1));
    const __m128i a2 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(c0 + k.d2));
    const __m128i a3 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(c0 + stride_r + stride_g + stride_b));
    __m128i acc = _mm_add_epi32(_mm_madd_epi16(_mm_unpacklo_epi16(a0, a1), wa),
                                _mm_madd_epi16(_mm_unpacklo_epi16(a2, a3), wb));
    acc = _mm_srli_epi32(_mm_add_epi32(acc, _mm_set1_epi32(kFracOne * kNodeScale / 2)), 15);
    const __m128i v16 = _mm_packs_epi32(acc, acc);
    return static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_packus_epi16(v16, v16)));
  }

  /// Up to four inks (lanes == kLane) of one colour, packed one per byte.
  std::uint32_t interpolate4(std::uint8_t r, std::uint8_t g, std::uint8_t b) const {
    return interpolate_lanes(corners(r, g, b), 0);
  }

  /// Fills `direct` with every colour's interpolation, on `threads` threads of the one pool.
  bool build_direct(int threads) {
    if (!direct.allocate(kDirectEntries * sizeof(std::uint32_t))) return false;
    for (std::uint32_t x = 0; x < 256; ++x) {
      direct_r[x] = (x >> 2) << 6 | (x & 3);
      direct_g[x] = (x >> 2) << 12 | (x & 3) << 2;
      direct_b[x] = (x >> 2) << 18 | (x & 3) << 4;
    }
    auto* out = static_cast<std::uint32_t*>(direct.data());
    auto fill = [this, out](int b0, int b1) {
      for (int b = b0; b < b1; ++b)
        for (int g = 0; g < 256; ++g)
          for (int r = 0; r < 256; ++r)
            out[direct_r[r] + direct_g[g] + direct_b[b]] =
                interpolate4(static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b));
    };
    // One blue plane per index: each worker writes its own planes, so the table never depends
    // on the thread count.
    ThreadPool pool(std::clamp(threads, 1, 16));
    pool.parallel_for(256, [&fill](int b, int) { fill(b, b + 1); });
    return true;
  }
#endif

  /// Device-value printing: the inks `device_channel` names from a 16-bit sRGB node, others none.
  void device_values(const std::uint16_t* rgb16, double* ink) const {
    for (int c = 0; c < channels; ++c) {
      const int k = device_channel[static_cast<size_t>(c)];
      ink[c] = k < 0 ? 0.0 : 1.0 - rgb16[k] / 65535.0;
    }
  }

  /// Linearisation then the ink limit, on fractions 0..1.
  void finish_inks(double* ink) const {
    for (int c = 0; c < channels; ++c) {
      ink[c] = std::clamp(ink[c], 0.0, 1.0);
      if (static_cast<size_t>(c) < curves.size() && !curves[c].points.empty()) ink[c] = evaluate(curves[c], ink[c]);
    }
    double sum = 0, k = 0;
    for (int c = 0; c < channels; ++c) (black[c] ? k : sum) += ink[c];
    if (sum + k <= limit_fraction) return;
    // Colour inks give way first: black carries the shadow detail and costs the least ink for it.
    if (k >= limit_fraction) {
      for (int c = 0; c < channels; ++c) ink[c] = black[c] ? ink[c] * limit_fraction / k : 0.0;
      return;
    }
    const double s = (limit_fraction - k) / sum;
    for (int c = 0; c < channels; ++c)
      if (!black[c]) ink[c] *= s;
  }
};

Result<InkConverter> InkConverter::create(const InkConverterSettings& s) {
  lcms::install_error_handler();
  auto t = std::make_shared<Table>();
  t->channels = static_cast<int>(s.ink_names.size());
  t->names = s.ink_names;
  if (t->channels < 1 || t->channels > kMaxInks)
    return fail(ErrorCode::kColour, fmt::format("ink converter: {} inks (1..{} supported)", t->channels, kMaxInks));
  if (s.grid_points < kMinGrid || s.grid_points > kMaxGrid)
    return fail(ErrorCode::kColour, fmt::format("ink converter: grid_points {} outside {}..{}", s.grid_points,
                                                kMinGrid, kMaxGrid));
  if (!(s.ink_limit_percent == 0 || (s.ink_limit_percent >= 100 && s.ink_limit_percent <= 100.0 * t->channels)))
    return fail(ErrorCode::kColour, fmt::format("ink converter: ink_limit_percent {} must be 0 (none) or 100..{}",
                                                s.ink_limit_percent, 100 * t->channels));
  if (!s.linearisation.empty() && s.linearisation.size() != s.ink_names.size())
    return fail(ErrorCode::kColour, fmt::format("ink converter: {} linearisation curves for {} inks",
                                                s.linearisation.size(), s.ink_names.size()));
  for (size_t c = 0; c < s.linearisation.size(); ++c) {
    if (s.linearisation[c].points.empty()) continue;
    auto ok = validate_tone_curve(s.linearisation[c], "ink '" + s.ink_names[c] + "' linearisation");
    if (!ok) return std::unexpected(ok.error());
  }
  t->curves = s.linearisation;
  for (const auto& n : s.ink_names) t->black.push_back(is_black(n));
  t->device_channel.assign(s.ink_names.size(), -1);
  if (!s.device_inks.empty()) {
    // Device values: each named ink follows one design channel, nothing else prints.
    if (s.device_inks.size() > 3)
      return fail(
          ErrorCode::kColour,
          fmt::format("ink converter: device_inks names {} inks; R, G and B drive at most 3", s.device_inks.size()));
    if (!s.calibration_profile.empty())
      return fail(ErrorCode::kColour,
                  "ink converter: device_inks prints device values; a calibration profile cannot apply");
    for (size_t k = 0; k < s.device_inks.size(); ++k) {
      const auto it = std::find(s.ink_names.begin(), s.ink_names.end(), s.device_inks[k]);
      if (it == s.ink_names.end())
        return fail(ErrorCode::kColour,
                    fmt::format("ink converter: device_inks: '{}' is not one of the printer's inks ({})",
                                s.device_inks[k], fmt::join(s.ink_names, ", ")));
      int& slot = t->device_channel[static_cast<size_t>(it - s.ink_names.begin())];
      if (slot >= 0)
        return fail(ErrorCode::kColour, fmt::format("ink converter: device_inks names '{}' twice", s.device_inks[k]));
      slot = static_cast<int>(k);
    }
    t->device_mode = true;
  }

  // The printer profile: named; or the default CMYK one for a plain CMYK printer; or, for inks
  // with typical solids, one built from them.
  std::filesystem::path path = s.profile_path;
  std::string pname = path.string();
  const std::vector<std::string> cmyk{"cyan", "magenta", "yellow", "black"};
  std::error_code ec;
  if (path.empty() && s.ink_names == cmyk && std::filesystem::is_regular_file(kDefaultCmykProfilePath, ec)) {
    path = kDefaultCmykProfilePath;
    pname = path.string();
  }
  if (path.empty()) {
    MultiInkProfileSpec spec;
    for (const auto& name : s.ink_names) {
      auto solid = typical_ink(name);
      if (!solid)
        return fail(ErrorCode::kColour, fmt::format("ink converter: ink '{}' has no typical colour; name a printer profile", name));
      spec.inks.push_back(*solid);
    }
    auto bytes = build_multi_ink_profile(spec);
    if (!bytes) return std::unexpected(bytes.error());
    pname = "synthetic profile of inks " + fmt::format("{}", fmt::join(s.ink_names, ","));
    t->profile.reset(cmsOpenProfileFromMem(bytes->data(), static_cast<cmsUInt32Number>(bytes->size())));
    if (!t->profile) return fail(ErrorCode::kColour, pname + ": lcms2 cannot read it back");
    logger().info("no printer profile named: using a {}", pname);
  } else {
    if (!std::filesystem::is_regular_file(path, ec)) return fail(ErrorCode::kColour, pname + ": no such printer profile");
    t->profile.reset(cmsOpenProfileFromFile(pname.c_str(), "r"));
    if (!t->profile) return fail(ErrorCode::kColour, pname + ": not a readable ICC profile");
  }
  if (cmsGetDeviceClass(t->profile.get()) != cmsSigOutputClass)
    return fail(ErrorCode::kColour, pname + ": not an output (printer) profile");
  const int prof_channels = static_cast<int>(cmsChannelsOf(cmsGetColorSpace(t->profile.get())));
  if (prof_channels != t->channels)
    return fail(ErrorCode::kColour, fmt::format("{}: profile has {} colourants but the printer has {} inks", pname,
                                                prof_channels, t->channels));

  lcms::Profile srgb(cmsCreate_sRGBProfile());
  const cmsUInt32Number intent = lcms_intent(s.intent);
  const cmsUInt32Number ink16 = CHANNELS_SH(t->channels) | BYTES_SH(2);
  const cmsUInt32Number ink_dbl = FLOAT_SH(1) | CHANNELS_SH(t->channels) | BYTES_SH(0);
  // Unoptimised transforms evaluate the profile's own tables, not an lcms2 precalculated grid.
  const cmsUInt32Number flags = cmsFLAGS_BLACKPOINTCOMPENSATION | cmsFLAGS_NOOPTIMIZE | cmsFLAGS_NOCACHE;
  lcms::Transform to_ink16(cmsCreateTransform(srgb.get(), TYPE_RGB_16, t->profile.get(), ink16, intent, flags));
  lcms::Transform exact(cmsCreateTransform(srgb.get(), TYPE_RGB_DBL, t->profile.get(), ink_dbl, intent, flags));
  if (!s.calibration_profile.empty()) {
    // sRGB -> the calibration profile's device RGB (its forward model inverted exactly,
    // rip/colour/profile_inverse.h) -> the separation the chart was printed with -> inks.
    auto inverse = RgbProfileInverse::open(s.calibration_profile);
    if (!inverse) return fail(ErrorCode::kColour, "calibration: " + inverse.error().message);
    t->calibration = std::make_unique<RgbProfileInverse>(std::move(*inverse));
    pname += " after calibration " + s.calibration_profile.string();
  }
  t->exact = std::move(exact);
  if (!to_ink16 || !t->exact)
    return fail(ErrorCode::kColour, pname + ": lcms2 cannot build an sRGB-to-ink transform for this intent");

  const int g = s.grid_points, nc = t->channels;
  t->grid = g;
  // Device values are printed as asked: a chart that finds the ink limit must not be held by one.
  const bool limited = s.ink_limit_percent > 0 && !t->device_mode;
  const int limit_percent = limited ? static_cast<int>(s.ink_limit_percent) : 100 * nc;
  t->limit_8bit = std::min(255 * nc, limit_percent * 255 / 100);
  // Nodes stay channels/2 units under the limit: per-channel rounding after interpolation adds at
  // most 1/2 unit each.
  t->limit_fraction = limited ? (t->limit_8bit - 0.5 * nc) / 255.0 : static_cast<double>(nc);

  // Evaluate every node through the profile in one call.
  const size_t n_nodes = static_cast<size_t>(g) * g * g;
  std::vector<std::uint16_t> rgb(n_nodes * 3), ink(n_nodes * nc);
  for (int r = 0, i = 0; r < g; ++r)
    for (int gg = 0; gg < g; ++gg)
      for (int b = 0; b < g; ++b, ++i) {
        rgb[3 * i + 0] = static_cast<std::uint16_t>(std::lround(r * 65535.0 / (g - 1)));
        rgb[3 * i + 1] = static_cast<std::uint16_t>(std::lround(gg * 65535.0 / (g - 1)));
        rgb[3 * i + 2] = static_cast<std::uint16_t>(std::lround(b * 65535.0 / (g - 1)));
      }
  std::vector<double> calibrated;
  if (t->calibration) {
    std::vector<std::array<double, 3>> srgb_nodes(n_nodes);
    for (size_t i = 0; i < n_nodes; ++i)
      for (int c = 0; c < 3; ++c) srgb_nodes[i][c] = rgb[3 * i + c] / 65535.0;
    const auto device_rgb = t->calibration->device_for_srgb(srgb_nodes);
    calibrated.resize(n_nodes * nc);
    cmsDoTransform(t->exact.get(), device_rgb.data(), calibrated.data(), static_cast<cmsUInt32Number>(n_nodes));
  } else {
    cmsDoTransform(to_ink16.get(), rgb.data(), ink.data(), static_cast<cmsUInt32Number>(n_nodes));
  }
  t->lanes = (nc + kLane - 1) / kLane * kLane;
  t->nodes.assign(n_nodes * t->lanes, 0);
  std::vector<double> v(nc);
  for (size_t i = 0; i < n_nodes; ++i) {
    for (int c = 0; c < nc; ++c) v[c] = t->calibration ? calibrated[i * nc + c] : ink[i * nc + c] / 65535.0;
    if (t->device_mode) t->device_values(&rgb[3 * i], v.data());
    t->finish_inks(v.data());
    for (int c = 0; c < nc; ++c)
      t->nodes[i * t->lanes + c] = static_cast<std::int16_t>(std::lround(v[c] * 255.0 * kNodeScale));
  }

  // Axis tables: input value -> (node offset, fraction), so the hot loop never divides.
  t->stride_b = static_cast<std::uint32_t>(t->lanes);
  t->stride_g = t->stride_b * g;
  t->stride_r = t->stride_g * g;
  for (int x = 0; x < 256; ++x) {
    const int pos = static_cast<int>(std::lround(x * (g - 1) * static_cast<double>(kFracOne) / 255.0));
    const int idx = std::min(pos / kFracOne, g - 2);
    const auto frac = static_cast<std::uint32_t>(pos - idx * kFracOne);
    t->axis_r[x] = {static_cast<std::uint32_t>(idx) * t->stride_r, frac};
    t->axis_g[x] = {static_cast<std::uint32_t>(idx) * t->stride_g, frac};
    t->axis_b[x] = {static_cast<std::uint32_t>(idx) * t->stride_b, frac};
  }
  // The six tetrahedra of the cube (two comparison patterns cannot occur; they get a valid one).
  const std::uint32_t R = t->stride_r, G = t->stride_g, B = t->stride_b;
  const Table::Tetra rgb_order{R, R + G};
  t->tetra = {{Table::Tetra{B, B + G},  // 0: b > g > r
              Table::Tetra{B, B + R},  // 1: b > r >= g
              Table::Tetra{G, G + B},  // 2: g >= b > r
              rgb_order,                        // 3: impossible
              rgb_order,                        // 4: impossible
              Table::Tetra{R, R + B},  // 5: r >= b > g
              Table::Tetra{G, G + R},  // 6: g > r >= b
              rgb_order}};                      // 7: r >= g >= b
#if defined(__SSE2__)
  if (s.direct_table && t->lanes == kLane &&
      !t->build_direct(static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))))
    logger().warn("{}: no memory for the direct colour table; interpolating per pixel", pname);
#endif
  logger().debug("{}: {}^3 ink table for {} inks, limit {} (8-bit units)", pname, g, nc, t->limit_8bit);
  return InkConverter(std::move(t));
}

int InkConverter::channels() const { return table_->channels; }
const std::vector<std::string>& InkConverter::ink_names() const { return table_->names; }
int InkConverter::ink_limit_8bit() const { return table_->limit_8bit; }

bool InkConverter::convert_row(const geometry::Rgba8* in, int n, std::uint8_t* const* out) const {
  const Table& t = *table_;
  const int nc = t.channels, lanes = t.lanes;
  // Byte stores may alias anything: keep the plane pointers in a local array the stores cannot
  // reach, or the compiler reloads them after every store.
  std::uint8_t* plane[16];
  for (int c = 0; c < nc; ++c) plane[c] = out[c];
  std::uint32_t last_rgb = 0xffffffffu;  // never a real key: keys have a zero top byte
  alignas(16) std::uint8_t last_ink[16] = {};
  bool any = false;
#if defined(__SSE2__)
  if (lanes == kLane) {
    // Up to four inks, in blocks: first every pixel's inks packed in 32 bits (no stores into the
    // planes between interpolations, so consecutive pixels overlap in the pipeline), then the
    // block is split into planes and scaled by coverage.
    constexpr int kBlock = 256;
    alignas(16) std::uint32_t packed[kBlock];
    const auto* direct = static_cast<const std::uint32_t*>(t.direct.data());
    std::uint32_t ink4 = 0;
    for (int i0 = 0; i0 < n; i0 += kBlock) {
      const int m = std::min(kBlock, n - i0);
      bool block_any = false;
      if (direct) {
        for (int j = 0; j < m; ++j) {
          const geometry::Rgba8 p = in[i0 + j];
          block_any |= p.a != 0;
          packed[j] = direct[t.direct_r[p.r] + t.direct_g[p.g] + t.direct_b[p.b]];
        }
      } else {
        for (int j = 0; j < m; ++j) {
          const geometry::Rgba8 p = in[i0 + j];
          const std::uint32_t key = p.r | (p.g << 8) | (p.b << 16);
          block_any |= p.a != 0;
          if (key != last_rgb) {
            last_rgb = key;
            ink4 = t.interpolate4(p.r, p.g, p.b);
          }
          packed[j] = ink4;
        }
      }
      any |= block_any;
      // Coverage scales every ink by a/255 rounding down (a = 255 keeps them, a = 0 clears them),
      // so scaled inks never exceed the limit.
      auto split = [&](int j0, int j1) {
        for (int j = j0; j < j1; ++j) {
          const std::uint32_t a = in[i0 + j].a;
          const std::uint32_t scale = a == 255 ? 65536u : a * 257u + 1u - (a == 0);
          const std::uint32_t v = packed[j];
          for (int c = 0; c < nc; ++c) plane[c][i0 + j] = static_cast<std::uint8_t>((((v >> (8 * c)) & 0xffu) * scale) >> 16);
        }
      };
      int j0 = 0;
      if (nc == kLane) {
        // Sixteen opaque pixels at a time: the packed inks transposed into the four planes.
        const __m128i amask = _mm_set1_epi32(static_cast<int>(0xff000000u));
        for (; j0 + 16 <= m; j0 += 16) {
          const auto* px = reinterpret_cast<const __m128i*>(in + i0 + j0);
          const __m128i opaque = _mm_and_si128(_mm_and_si128(_mm_loadu_si128(px), _mm_loadu_si128(px + 1)),
                                               _mm_and_si128(_mm_loadu_si128(px + 2), _mm_loadu_si128(px + 3)));
          if (_mm_movemask_epi8(_mm_cmpeq_epi32(_mm_and_si128(opaque, amask), amask)) != 0xffff) {
            split(j0, j0 + 16);
            continue;
          }
          const auto* pk = reinterpret_cast<const __m128i*>(packed + j0);
          const __m128i a = _mm_load_si128(pk), b = _mm_load_si128(pk + 1);
          const __m128i c = _mm_load_si128(pk + 2), d = _mm_load_si128(pk + 3);
          // Bytes (ink, pixel): three rounds of interleaving turn pixel-major into ink-major.
          const __m128i t0 = _mm_unpacklo_epi8(a, b), t1 = _mm_unpackhi_epi8(a, b);
          const __m128i t2 = _mm_unpacklo_epi8(c, d), t3 = _mm_unpackhi_epi8(c, d);
          const __m128i u0 = _mm_unpacklo_epi8(t0, t1), u1 = _mm_unpackhi_epi8(t0, t1);
          const __m128i u2 = _mm_unpacklo_epi8(t2, t3), u3 = _mm_unpackhi_epi8(t2, t3);
          const __m128i v0 = _mm_unpacklo_epi8(u0, u1), v1 = _mm_unpackhi_epi8(u0, u1);
          const __m128i w0 = _mm_unpacklo_epi8(u2, u3), w1 = _mm_unpackhi_epi8(u2, u3);
          _mm_storeu_si128(reinterpret_cast<__m128i*>(plane[0] + i0 + j0), _mm_unpacklo_epi64(v0, w0));
          _mm_storeu_si128(reinterpret_cast<__m128i*>(plane[1] + i0 + j0), _mm_unpackhi_epi64(v0, w0));
          _mm_storeu_si128(reinterpret_cast<__m128i*>(plane[2] + i0 + j0), _mm_unpacklo_epi64(v1, w1));
          _mm_storeu_si128(reinterpret_cast<__m128i*>(plane[3] + i0 + j0), _mm_unpackhi_epi64(v1, w1));
        }
      }
      split(j0, m);
    }
    return any;
  }
#endif
  for (int i = 0; i < n; ++i) {
    const geometry::Rgba8 p = in[i];
    if (p.a == 0) {
      for (int c = 0; c < nc; ++c) plane[c][i] = 0;
      continue;
    }
    any = true;
    const std::uint32_t key = p.r | (p.g << 8) | (p.b << 16);
    if (key != last_rgb) {
      last_rgb = key;
      const Table::Corners k = t.corners(p.r, p.g, p.b);
#if defined(__SSE2__)
      for (int g = 0; g < lanes; g += kLane) {
        const std::uint32_t four = t.interpolate_lanes(k, g);
        std::memcpy(last_ink + g, &four, 4);
      }
#else
      const std::int16_t* corner[4] = {k.c0, k.c0 + k.d1, k.c0 + k.d2, k.c0 + t.stride_r + t.stride_g + t.stride_b};
      for (int c = 0; c < nc; ++c) {
        std::int32_t acc = 0;
        for (int q = 0; q < 4; ++q) acc += corner[q][c] * static_cast<std::int32_t>(k.w[q]);
        last_ink[c] = static_cast<std::uint8_t>((acc + kFracOne * kNodeScale / 2) / (kFracOne * kNodeScale));
      }
#endif
    }
    if (p.a == 255) {
      for (int c = 0; c < nc; ++c) plane[c][i] = last_ink[c];
    } else {
      // Partial coverage: scale by a/255 rounding down, so scaled inks never exceed the limit.
      const std::uint32_t scale = p.a * 257u + 1u;
      for (int c = 0; c < nc; ++c) plane[c][i] = static_cast<std::uint8_t>((last_ink[c] * scale) >> 16);
    }
  }
  return any;
}

std::vector<double> InkConverter::convert_exact(geometry::Rgba8 colour) const {
  const Table& t = *table_;
  std::array<double, 3> rgb{colour.r / 255.0, colour.g / 255.0, colour.b / 255.0};
  if (t.calibration) rgb = t.calibration->device_for_srgb({rgb}).front();
  std::vector<double> ink(t.channels);
  if (t.device_mode) {
    const std::uint16_t rgb16[3] = {static_cast<std::uint16_t>(colour.r * 257),
                                    static_cast<std::uint16_t>(colour.g * 257),
                                    static_cast<std::uint16_t>(colour.b * 257)};
    t.device_values(rgb16, ink.data());
  } else {
    cmsDoTransform(t.exact.get(), rgb.data(), ink.data(), 1);
  }
  t.finish_inks(ink.data());
  return ink;
}

}  // namespace tp::rip
