// rip/colour/ink_converter.h: design colours (sRGB) to the printer's ink amounts through an ICC
// output profile, precomputed into a lookup table for the hot path.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/common/image.h"
#include "rip/colour/tone_curve.h"
#include "rip/common/error.h"

namespace tp::rip {

/// CMYK output profile used when a 4-ink CMYK printer names none (Ghostscript's, package
/// libgs10-common).
inline constexpr const char* kDefaultCmykProfilePath = "/usr/share/ghostscript/10.00.0/iccprofiles/default_cmyk.icc";

enum class RenderingIntent { kPerceptual, kRelativeColorimetric, kSaturation, kAbsoluteColorimetric };

/// How to separate colours into inks.
struct InkConverterSettings {
  /// Printer output profile with one channel per ink, in ink order. Empty: kDefaultCmykProfilePath
  /// when the inks are cyan, magenta, yellow, black (and it is installed); otherwise a profile
  /// built from the inks' typical solids (build_multi_ink_profile), if every ink has one.
  std::filesystem::path profile_path;
  std::vector<std::string> ink_names{"cyan", "magenta", "yellow", "black"};
  RenderingIntent intent = RenderingIntent::kPerceptual;
  /// Empty, or an RGB output profile of this printer as driven through this very separation (a
  /// calibration set's, docs/colour.md): design sRGB is first mapped, relative colorimetric,
  /// to the sRGB values that reproduce it on the fabric, then separated as usual.
  std::filesystem::path calibration_profile;
  /// Total ink limit (sum over inks, percent of one solid ink), e.g. 280; 0 = no limit. Applied to
  /// the linearised amounts, reducing colour inks before black.
  double ink_limit_percent = 0;
  /// Empty, or one curve per ink (an empty curve is the identity).
  std::vector<ToneCurve> linearisation;
  /// Empty, or up to three ink names driven directly by the design's R, G and B (ink amount =
  /// 1 - value / 255, every other ink none): device-value printing for calibration charts
  /// (drop-limit, linearisation and ink-limit charts, docs/colour.md). The printer profile and
  /// calibration profile are not used and the ink limit is off; the linearisation curves still
  /// apply, so a chart can be printed through the curves already measured.
  std::vector<std::string> device_inks;
  /// LUT nodes per sRGB axis (3D lookup, tetrahedral interpolation): 9..65.
  int grid_points = 33;
  /// Also interpolate every 8-bit sRGB colour once, at creation (up to four inks: 64 MiB, about
  /// 0.1 s on 2 cores), so a pixel's conversion is one lookup. Same results as without; worth it
  /// for jobs of more than a few tens of megapixels.
  bool direct_table = false;
};

/// Converts sRGB pixels to 8-bit ink amounts (0 = none, 255 = solid). Immutable after creation
/// and safe to use from several threads; cheap to copy (shares its table).
///
/// The table holds, at every grid node, the profile's separation (lcms2, full precision), then the
/// linearisation curves, then the ink limit; pixels interpolate it tetrahedrally in integer
/// arithmetic. Interpolation is a convex combination of nodes that obey the limit and rounding is
/// budgeted for, so every output pixel obeys the ink limit exactly. Alpha (piece-edge coverage or
/// design transparency over unprinted fabric) scales every ink.
class InkConverter {
 public:
  /// Builds the table. Fails (kColour) naming the profile file: missing or unreadable profile, not
  /// an output profile with one channel per ink, no transform for the intent, bad curves or limit.
  [[nodiscard]] static Result<InkConverter> create(const InkConverterSettings& settings);

  int channels() const;
  const std::vector<std::string>& ink_names() const;
  /// The limit in 8-bit units summed over inks (channels * 255 when unlimited).
  int ink_limit_8bit() const;

  /// Converts `n` pixels: out[c][i] receives ink c of pixel i. Returns false when every pixel had
  /// alpha 0 (no ink anywhere), in which case the outputs are zero.
  bool convert_row(const geometry::Rgba8* in, int n, std::uint8_t* const* out) const;

  /// Ink amounts (0..1) of one opaque sRGB colour computed at full precision without the table,
  /// with the same curves and limit: the reference the table approximates.
  std::vector<double> convert_exact(geometry::Rgba8 colour) const;

 private:
  struct Table;
  explicit InkConverter(std::shared_ptr<const Table> table) : table_(std::move(table)) {}
  std::shared_ptr<const Table> table_;
};

}  // namespace tp::rip
