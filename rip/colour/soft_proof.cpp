// rip/colour/soft_proof.cpp: the sRGB -> printer -> sRGB chain with lcms2 and the gamut tally.
#include "rip/colour/soft_proof.h"

#include <lcms2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "device/colour/colorimetry.h"
#include "rip/colour/internal/lcms_handles.h"
#include "rip/colour/profile_inverse.h"
#include "rip/colour/proof_check.h"

namespace tp::rip {
namespace {

// The design's colour decides its proof's (one transform for the whole image), so the colour
// difference is computed once per design colour: a marker of tens of megapixels holds far
// fewer colours. Direct-mapped on the colour's low 20 bits; a clash computes afresh, the
// figure is the same either way.
class DeltaEMemo {
 public:
  DeltaEMemo() : slots_(std::size_t{1} << kBits, Slot{kEmpty, 0}) {}

  double get(const geometry::Rgba8& design, const geometry::Rgba8& proof) {
    const std::uint32_t key = (static_cast<std::uint32_t>(design.r) << 16) | (design.g << 8) | design.b;
    Slot& slot = slots_[key & ((std::uint32_t{1} << kBits) - 1)];
    if (slot.key != key) {
      slot.key = key;
      slot.de00 = device::delta_e_2000(device::xyz_to_lab(device::srgb8_to_xyz(design.r, design.g, design.b)),
                                       device::xyz_to_lab(device::srgb8_to_xyz(proof.r, proof.g, proof.b)));
    }
    return slot.de00;
  }

 private:
  static constexpr int kBits = 20;
  static constexpr std::uint32_t kEmpty = 0xffffffff;  // no 24-bit colour
  struct Slot {
    std::uint32_t key;
    double de00;
  };
  std::vector<Slot> slots_;
};

}  // namespace

Result<SoftProofSummary> soft_proof(const geometry::ImageRgba8& design, const std::filesystem::path& profile,
                                    geometry::ImageRgba8& proof, geometry::ImageRgba8* overlay) {
  const std::string pname = profile.string();
  lcms::Profile prof(cmsOpenProfileFromFile(pname.c_str(), "r"));
  if (!prof) return fail(ErrorCode::kColour, pname + ": not a readable ICC profile");
  proof = design;
  if (cmsGetColorSpace(prof.get()) == cmsSigRgbData) {
    // An RGB profile (a calibration set's): the exact inverse of its forward model, the one the
    // RIP separates with, so the proof shows what prints, not the B2A table's approximation.
    auto inverse = RgbProfileInverse::open(profile);
    if (!inverse) return fail(inverse.error());
    std::unordered_map<std::uint32_t, std::size_t> index;
    std::vector<std::array<double, 3>> colours;
    for (const geometry::Rgba8& d : design.pixels) {
      const std::uint32_t key = (static_cast<std::uint32_t>(d.r) << 16) | (d.g << 8) | d.b;
      if (index.emplace(key, colours.size()).second) colours.push_back({d.r / 255.0, d.g / 255.0, d.b / 255.0});
    }
    const std::vector<device::Lab> lab = inverse->colour_of(inverse->device_for_srgb(colours));
    lcms::Profile lab_profile(cmsCreateLab4Profile(nullptr)), srgb(cmsCreate_sRGBProfile());
    lcms::Transform to_srgb(cmsCreateTransform(lab_profile.get(), TYPE_Lab_DBL, srgb.get(), TYPE_RGB_DBL,
                                               INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_NOCACHE));
    if (!to_srgb) return fail(ErrorCode::kColour, pname + ": lcms2 cannot build the soft-proof transform");
    std::vector<cmsCIELab> in(lab.size());
    for (std::size_t i = 0; i < lab.size(); ++i) in[i] = {lab[i].l, lab[i].a, lab[i].b};
    std::vector<std::array<double, 3>> out(lab.size());
    if (!in.empty()) cmsDoTransform(to_srgb.get(), in.data(), out.data(), static_cast<cmsUInt32Number>(in.size()));
    auto q = [](double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    for (geometry::Rgba8& p : proof.pixels) {
      const std::array<double, 3>& c = out[index.at((static_cast<std::uint32_t>(p.r) << 16) | (p.g << 8) | p.b)];
      p = {q(c[0]), q(c[1]), q(c[2]), p.a};
    }
  } else {
    lcms::Profile srgb_in(cmsCreate_sRGBProfile()), srgb_out(cmsCreate_sRGBProfile());
    // Printer profile as output then as input: the colour it gives for each design colour.
    cmsHPROFILE chain[4] = {srgb_in.get(), prof.get(), prof.get(), srgb_out.get()};
    lcms::Transform t(cmsCreateMultiprofileTransform(chain, 4, TYPE_RGBA_8, TYPE_RGBA_8, INTENT_RELATIVE_COLORIMETRIC,
                                                     cmsFLAGS_COPY_ALPHA | cmsFLAGS_HIGHRESPRECALC));
    if (!t) return fail(ErrorCode::kColour, pname + ": lcms2 cannot build the soft-proof transform");
    cmsDoTransform(t.get(), design.pixels.data(), proof.pixels.data(),
                   static_cast<cmsUInt32Number>(design.pixels.size()));
  }
  if (overlay) *overlay = proof;
  SoftProofSummary s;
  std::size_t oog = 0;
  DeltaEMemo memo;
  for (std::size_t i = 0; i < design.pixels.size(); ++i) {
    const geometry::Rgba8& d = design.pixels[i];
    if (d.a == 0 || (d.r >= 250 && d.g >= 250 && d.b >= 250)) {
      proof.pixels[i] = d;
      if (overlay) overlay->pixels[i] = d;
      continue;
    }
    ++s.printed_pixels;
    const double de = memo.get(d, proof.pixels[i]);
    s.worst_de00 = std::max(s.worst_de00, de);
    if (de > kGamutTolerance_de00) {
      ++oog;
      if (overlay) overlay->pixels[i] = {0, 255, 0, d.a};
    }
  }
  s.out_of_gamut_share = s.printed_pixels ? static_cast<double>(oog) / static_cast<double>(s.printed_pixels) : 0.0;
  return s;
}

}  // namespace tp::rip
