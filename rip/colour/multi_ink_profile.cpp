// rip/colour/multi_ink_profile.cpp: a density-additive ink model, its hue-sector inversion, and the
// ICC v4 output profile (AToB/BToA tables, colorant table) built from them with lcms2.
#include "rip/colour/multi_ink_profile.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numbers>

#include <lcms2.h>
#include <spdlog/fmt/fmt.h>

#include "rip/colour/internal/lcms_handles.h"

namespace tp::rip {

namespace {

/// A pivot below this makes the fit's system singular.
constexpr double kSingularPivot = 1e-12;
/// Two fit errors this close are a tie, broken by the ink order so the choice is deterministic.
constexpr double kTieSlack = 1e-12;

constexpr int kMaxInks = 15;
/// Inks of lower chroma than this (CIELAB C*) are achromatic: black (only one is supported).
constexpr double kAchromaticChroma = 12;
/// Two chromatic inks closer in hue than this cannot both be hue neighbours.
constexpr double kMinHueSeparationDeg = 5;
/// Forward (AToB) table nodes stay under this count whatever the number of inks.
constexpr double kMaxForwardNodes = 400000;
constexpr double kMinDensity = 1e-4;  ///< an ink must darken at least one XYZ band by this much

using Vec3 = std::array<double, 3>;

/// The ink model in media-relative terms: paper = PCS white, ink i = densities d_i in X, Y, Z.
struct InkModel {
  std::vector<Vec3> density;   ///< per ink: -ln(solid / paper) per XYZ band
  std::vector<int> chromatic;  ///< chromatic inks in increasing density hue
  std::vector<double> hue;     ///< their density hues, radians
  int black = -1;
  Vec3 e1{}, e2{};             ///< basis of the density plane orthogonal to black (or to grey)

  /// Hue of a density vector: its angle in the plane orthogonal to black. A mix of two inks plus
  /// black always has a hue between theirs, which makes the sector choice exact.
  double density_hue(const Vec3& d) const {
    const double x = d[0] * e1[0] + d[1] * e1[1] + d[2] * e1[2], y = d[0] * e2[0] + d[1] * e2[1] + d[2] * e2[2];
    return std::atan2(y, x);
  }
};

Vec3 normalised(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

Vec3 lab_to_xyz(double L, double a, double b) {
  cmsCIELab lab{L, a, b};
  cmsCIEXYZ xyz;
  cmsLab2XYZ(cmsD50_XYZ(), &xyz, &lab);
  return {xyz.X, xyz.Y, xyz.Z};
}

cmsCIELab xyz_to_lab(const Vec3& v) {
  cmsCIEXYZ xyz{v[0], v[1], v[2]};
  cmsCIELab lab;
  cmsXYZ2Lab(cmsD50_XYZ(), &lab, &xyz);
  return lab;
}

/// Media-relative PCS colour of ink amounts (0..1 each): the paper's white dimmed by every ink.
Vec3 forward(const InkModel& m, const double* amount) {
  const cmsCIEXYZ* w = cmsD50_XYZ();
  Vec3 d{0, 0, 0};
  for (size_t i = 0; i < m.density.size(); ++i)
    for (int k = 0; k < 3; ++k) d[k] += amount[i] * m.density[i][k];
  return {w->X * std::exp(-d[0]), w->Y * std::exp(-d[1]), w->Z * std::exp(-d[2])};
}

/// Bounded least squares over at most 3 inks: min |sum a_i d_i - target|^2, 0 <= a_i <= 1, by
/// trying every pattern of inks at 0, at 1 or free (27 at most) and keeping the best feasible one.
std::vector<double> solve_bounded(const std::vector<Vec3>& cols, const Vec3& target) {
  const int n = static_cast<int>(cols.size());
  std::vector<double> best(static_cast<size_t>(n), 0.0);
  double best_err = 1e300, best_ink = 1e300;
  int patterns = 1;
  for (int i = 0; i < n; ++i) patterns *= 3;
  for (int p = 0; p < patterns; ++p) {
    std::vector<int> state(static_cast<size_t>(n));
    for (int i = 0, q = p; i < n; ++i, q /= 3) state[static_cast<size_t>(i)] = q % 3;  // 0: zero, 1: one, 2: free
    std::vector<double> a(static_cast<size_t>(n), 0.0);
    Vec3 rhs = target;
    std::vector<int> free_idx;
    for (int i = 0; i < n; ++i) {
      if (state[static_cast<size_t>(i)] == 1) {
        a[static_cast<size_t>(i)] = 1;
        for (int k = 0; k < 3; ++k) rhs[k] -= cols[static_cast<size_t>(i)][k];
      } else if (state[static_cast<size_t>(i)] == 2) {
        free_idx.push_back(i);
      }
    }
    // Normal equations for the free inks (at most 3x3), solved by Gaussian elimination.
    const int f = static_cast<int>(free_idx.size());
    double A[3][4] = {};
    for (int r = 0; r < f; ++r) {
      for (int c = 0; c < f; ++c)
        for (int k = 0; k < 3; ++k) A[r][c] += cols[static_cast<size_t>(free_idx[r])][k] * cols[static_cast<size_t>(free_idx[c])][k];
      for (int k = 0; k < 3; ++k) A[r][f] += cols[static_cast<size_t>(free_idx[r])][k] * rhs[k];
    }
    bool ok = true;
    for (int c = 0; c < f && ok; ++c) {
      int piv = c;
      for (int r = c + 1; r < f; ++r)
        if (std::abs(A[r][c]) > std::abs(A[piv][c])) piv = r;
      if (std::abs(A[piv][c]) < kSingularPivot) {
        ok = false;
        break;
      }
      for (int k = 0; k <= f; ++k) std::swap(A[c][k], A[piv][k]);
      for (int r = 0; r < f; ++r) {
        if (r == c) continue;
        const double q = A[r][c] / A[c][c];
        for (int k = c; k <= f; ++k) A[r][k] -= q * A[c][k];
      }
    }
    if (!ok) continue;
    for (int r = 0; r < f; ++r) {
      const double v = A[r][f] / A[r][r];
      if (v < 0 || v > 1) ok = false;
      a[static_cast<size_t>(free_idx[r])] = v;
    }
    if (!ok) continue;
    double err = 0, ink = 0;
    for (int k = 0; k < 3; ++k) {
      double s = -target[k];
      for (int i = 0; i < n; ++i) s += a[static_cast<size_t>(i)] * cols[static_cast<size_t>(i)][k];
      err += s * s;
    }
    for (double v : a) ink += v;
    // Prefer the closer colour; between equally close ones (within rounding), less ink.
    if (err < best_err - kTieSlack || (std::abs(err - best_err) <= kTieSlack && ink < best_ink)) {
      best_err = err;
      best_ink = ink;
      best = a;
    }
  }
  return best;
}

/// Ink amounts for a media-relative Lab colour: black plus the two chromatic inks around its hue.
std::vector<double> separate(const InkModel& m, const cmsCIELab& lab) {
  const size_t n = m.density.size();
  std::vector<double> amount(n, 0.0);
  const Vec3 xyz = lab_to_xyz(lab.L, lab.a, lab.b);
  const cmsCIEXYZ* w = cmsD50_XYZ();
  const Vec3 target{-std::log(std::max(xyz[0], 1e-6) / w->X), -std::log(std::max(xyz[1], 1e-6) / w->Y),
                    -std::log(std::max(xyz[2], 1e-6) / w->Z)};
  std::vector<int> use;
  const int mc = static_cast<int>(m.chromatic.size());
  if (mc == 1) use.push_back(m.chromatic[0]);
  if (mc >= 2) {
    const double h = m.density_hue(target);
    int j = mc - 1;  // sector [hue[j], hue[j+1]) cyclically
    for (int i = 0; i < mc; ++i)
      if (m.hue[static_cast<size_t>(i)] <= h) j = i;
    use.push_back(m.chromatic[static_cast<size_t>(j)]);
    use.push_back(m.chromatic[static_cast<size_t>((j + 1) % mc)]);
  }
  if (m.black >= 0) use.push_back(m.black);
  std::vector<Vec3> cols;
  for (int i : use) cols.push_back(m.density[static_cast<size_t>(i)]);
  const std::vector<double> a = solve_bounded(cols, target);
  for (size_t k = 0; k < use.size(); ++k) amount[static_cast<size_t>(use[k])] = a[k];
  return amount;
}

cmsColorSpaceSignature colour_space_of(const std::vector<InkSolid>& inks) {
  static constexpr cmsColorSpaceSignature kByCount[] = {
      cmsSigGrayData,    cmsSigGrayData,    cmsSig2colorData,  cmsSig3colorData,  cmsSig4colorData,
      cmsSig5colorData,  cmsSig6colorData,  cmsSig7colorData,  cmsSig8colorData,  cmsSig9colorData,
      cmsSig10colorData, cmsSig11colorData, cmsSig12colorData, cmsSig13colorData, cmsSig14colorData,
      cmsSig15colorData};
  std::vector<std::string> names;
  for (const auto& i : inks) names.push_back(i.name);
  if (names == std::vector<std::string>{"cyan", "magenta", "yellow", "black"}) return cmsSigCmykData;
  return kByCount[inks.size()];
}

struct Cargo {
  const InkModel* model;
  int inks;
};

int sample_forward(const cmsUInt16Number in[], cmsUInt16Number out[], void* cargo) {
  const auto* c = static_cast<const Cargo*>(cargo);
  double a[kMaxInks];
  for (int i = 0; i < c->inks; ++i) a[i] = in[i] / 65535.0;
  const cmsCIELab lab = xyz_to_lab(forward(*c->model, a));
  cmsFloat2LabEncoded(out, &lab);
  return 1;
}

/// ICC v4 encodes a* = b* = 0 as 32896, between two nodes of any 2^k + 1 grid. The separation
/// table's input curves move it onto the middle node so that neutral colours, paper white above
/// all, are nodes: white then gets exactly no ink.
constexpr double kV4Zero = 32896, kMidNode = 32768;

double ab_to_node_axis(double x) {
  return x <= kV4Zero ? x * kMidNode / kV4Zero : kMidNode + (x - kV4Zero) * (65535 - kMidNode) / (65535 - kV4Zero);
}
double node_axis_to_ab(double y) {
  return y <= kMidNode ? y * kV4Zero / kMidNode : kV4Zero + (y - kMidNode) * (65535 - kV4Zero) / (65535 - kMidNode);
}

int sample_separation(const cmsUInt16Number in[], cmsUInt16Number out[], void* cargo) {
  const auto* c = static_cast<const Cargo*>(cargo);
  const cmsUInt16Number enc[3] = {in[0], static_cast<cmsUInt16Number>(std::lround(node_axis_to_ab(in[1]))),
                                  static_cast<cmsUInt16Number>(std::lround(node_axis_to_ab(in[2])))};
  cmsCIELab lab;
  cmsLabEncoded2Float(&lab, enc);
  const std::vector<double> a = separate(*c->model, lab);
  for (int i = 0; i < c->inks; ++i) out[i] = static_cast<cmsUInt16Number>(std::lround(std::clamp(a[static_cast<size_t>(i)], 0.0, 1.0) * 65535));
  return 1;
}

void set_text(cmsHPROFILE h, cmsTagSignature tag, const std::string& text) {
  cmsMLU* mlu = cmsMLUalloc(nullptr, 1);
  cmsMLUsetASCII(mlu, "en", "US", text.c_str());
  cmsWriteTag(h, tag, mlu);
  cmsMLUfree(mlu);
}

/// [input curves][CLUT][identity curves], the shape ICC v4 lutAtoB/lutBtoA tags take; identity
/// input curves unless `lab_input`, which gets the a*/b* centring curves.
cmsPipeline* clut_pipeline(int in, int out, int grid, cmsSAMPLER16 sampler, Cargo* cargo, bool lab_input) {
  cmsPipeline* p = cmsPipelineAlloc(nullptr, static_cast<cmsUInt32Number>(in), static_cast<cmsUInt32Number>(out));
  cmsStage* clut = cmsStageAllocCLut16bit(nullptr, static_cast<cmsUInt32Number>(grid), static_cast<cmsUInt32Number>(in),
                                          static_cast<cmsUInt32Number>(out), nullptr);
  cmsStageSampleCLut16bit(clut, sampler, cargo, 0);
  if (lab_input) {
    // 256 entries put x = 32896 (entry 128) exactly on the curve's knee.
    std::vector<cmsUInt16Number> table(256);
    for (int i = 0; i < 256; ++i) table[static_cast<size_t>(i)] = static_cast<cmsUInt16Number>(std::lround(ab_to_node_axis(i * 257.0)));
    cmsToneCurve* identity = cmsBuildGamma(nullptr, 1.0);
    cmsToneCurve* centre = cmsBuildTabulatedToneCurve16(nullptr, 256, table.data());
    cmsToneCurve* curves[3] = {identity, centre, centre};
    cmsPipelineInsertStage(p, cmsAT_END, cmsStageAllocToneCurves(nullptr, 3, curves));
    cmsFreeToneCurve(identity);
    cmsFreeToneCurve(centre);
  } else {
    cmsPipelineInsertStage(p, cmsAT_END, cmsStageAllocToneCurves(nullptr, static_cast<cmsUInt32Number>(in), nullptr));
  }
  cmsPipelineInsertStage(p, cmsAT_END, clut);
  cmsPipelineInsertStage(p, cmsAT_END, cmsStageAllocToneCurves(nullptr, static_cast<cmsUInt32Number>(out), nullptr));
  return p;
}

}  // namespace

std::optional<InkSolid> typical_ink(std::string_view name) {
  // Solids of reactive dyes on bleached cotton, rounded (D50, 2 degree observer).
  static const InkSolid kInks[] = {{"cyan", 55, -37, -50},  {"magenta", 48, 74, -3},  {"yellow", 89, -5, 93},
                                   {"black", 16, 0, 0},     {"red", 47, 68, 48},      {"orange", 63, 51, 75},
                                   {"blue", 30, 20, -58},   {"green", 50, -65, 25},   {"violet", 32, 45, -45}};
  for (const auto& i : kInks)
    if (i.name == name) return i;
  return std::nullopt;
}

Result<std::vector<std::uint8_t>> build_multi_ink_profile(const MultiInkProfileSpec& spec) {
  lcms::install_error_handler();
  const int n = static_cast<int>(spec.inks.size());
  if (n < 1 || n > kMaxInks) return fail(ErrorCode::kColour, fmt::format("ink profile: {} inks (1..{})", n, kMaxInks));
  if (spec.separation_grid < 9 || spec.separation_grid > 65)
    return fail(ErrorCode::kColour, fmt::format("ink profile: separation_grid {} outside 9..65", spec.separation_grid));

  // The model, relative to the paper: densities of each solid against the paper's XYZ.
  InkModel model;
  const Vec3 paper = lab_to_xyz(spec.paper_L, spec.paper_a, spec.paper_b);
  std::vector<int> chromatic;
  for (int i = 0; i < n; ++i) {
    const InkSolid& ink = spec.inks[static_cast<size_t>(i)];
    const Vec3 s = lab_to_xyz(ink.L, ink.a, ink.b);
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = std::max(0.0, -std::log(s[k] / paper[k]));
    if (d[0] + d[1] + d[2] < kMinDensity || !(ink.L < spec.paper_L))
      return fail(ErrorCode::kColour, fmt::format("ink profile: ink '{}' (L* {}) is not darker than the paper (L* {})",
                                                  ink.name, ink.L, spec.paper_L));
    model.density.push_back(d);
    if (std::hypot(ink.a, ink.b) < kAchromaticChroma) {
      if (model.black >= 0)
        return fail(ErrorCode::kColour, fmt::format("ink profile: inks '{}' and '{}' are both achromatic (one black only)",
                                                    spec.inks[static_cast<size_t>(model.black)].name, ink.name));
      model.black = i;
    } else {
      chromatic.push_back(i);
    }
  }
  // The hue plane: orthogonal to black's densities (or to equal densities without black).
  const Vec3 u = normalised(model.black >= 0 ? model.density[static_cast<size_t>(model.black)] : Vec3{1, 1, 1});
  const double ux = u[0];
  model.e1 = normalised({1 - ux * u[0], -ux * u[1], -ux * u[2]});
  model.e2 = {u[1] * model.e1[2] - u[2] * model.e1[1], u[2] * model.e1[0] - u[0] * model.e1[2],
              u[0] * model.e1[1] - u[1] * model.e1[0]};
  std::vector<std::pair<double, int>> hues;
  for (int i : chromatic) hues.emplace_back(model.density_hue(model.density[static_cast<size_t>(i)]), i);
  std::sort(hues.begin(), hues.end());
  for (size_t i = 0; i < hues.size(); ++i) {
    const size_t j = (i + 1) % hues.size();
    double gap = hues[j].first - hues[i].first;
    if (j == 0) gap += 2 * std::numbers::pi;
    if (hues.size() > 1 && gap * 180 / std::numbers::pi < kMinHueSeparationDeg)
      return fail(ErrorCode::kColour, fmt::format("ink profile: inks '{}' and '{}' have the same hue",
                                                  spec.inks[static_cast<size_t>(hues[i].second)].name,
                                                  spec.inks[static_cast<size_t>(hues[j].second)].name));
  }
  for (const auto& [h, i] : hues) {
    model.hue.push_back(h);
    model.chromatic.push_back(i);
  }

  // The profile: header, texts, media white (the paper), colorant names, then the two tables.
  lcms::Profile h(cmsCreateProfilePlaceholder(nullptr));
  cmsSetProfileVersion(h.get(), 4.3);
  cmsSetDeviceClass(h.get(), cmsSigOutputClass);
  cmsSetColorSpace(h.get(), colour_space_of(spec.inks));
  cmsSetPCS(h.get(), cmsSigLabData);
  cmsSetHeaderRenderingIntent(h.get(), INTENT_PERCEPTUAL);
  set_text(h.get(), cmsSigProfileDescriptionTag, spec.description);
  set_text(h.get(), cmsSigCopyrightTag, "No copyright, use freely");
  cmsCIEXYZ white{paper[0], paper[1], paper[2]};
  cmsWriteTag(h.get(), cmsSigMediaWhitePointTag, &white);
  cmsNAMEDCOLORLIST* names = cmsAllocNamedColorList(nullptr, static_cast<cmsUInt32Number>(n), 0, "", "");
  for (const auto& ink : spec.inks) {
    cmsCIELab lab{ink.L, ink.a, ink.b};
    cmsUInt16Number pcs[3];
    cmsFloat2LabEncoded(pcs, &lab);
    cmsAppendNamedColor(names, ink.name.c_str(), pcs, nullptr);
  }
  cmsWriteTag(h.get(), cmsSigColorantTableTag, names);
  cmsFreeNamedColorList(names);

  Cargo cargo{&model, n};
  const int fwd_grid = std::clamp(static_cast<int>(std::floor(std::pow(kMaxForwardNodes, 1.0 / n))), 2, 17);
  cmsPipeline* a2b = clut_pipeline(n, 3, fwd_grid, sample_forward, &cargo, false);
  cmsPipeline* b2a = clut_pipeline(3, n, spec.separation_grid, sample_separation, &cargo, true);
  const bool written = cmsWriteTag(h.get(), cmsSigAToB0Tag, a2b) && cmsWriteTag(h.get(), cmsSigBToA0Tag, b2a) &&
                       cmsLinkTag(h.get(), cmsSigAToB1Tag, cmsSigAToB0Tag) && cmsLinkTag(h.get(), cmsSigBToA1Tag, cmsSigBToA0Tag) &&
                       cmsLinkTag(h.get(), cmsSigAToB2Tag, cmsSigAToB0Tag) && cmsLinkTag(h.get(), cmsSigBToA2Tag, cmsSigBToA0Tag);
  cmsPipelineFree(a2b);
  cmsPipelineFree(b2a);
  if (!written) return fail(ErrorCode::kColour, "ink profile: lcms2 refused the tables");

  cmsUInt32Number size = 0;
  if (!cmsSaveProfileToMem(h.get(), nullptr, &size) || size == 0)
    return fail(ErrorCode::kColour, "ink profile: lcms2 cannot serialise the profile");
  std::vector<std::uint8_t> bytes(size);
  if (!cmsSaveProfileToMem(h.get(), bytes.data(), &size)) return fail(ErrorCode::kColour, "ink profile: serialising failed");
  bytes.resize(size);
  return bytes;
}

Status write_multi_ink_profile(const MultiInkProfileSpec& spec, const std::filesystem::path& path) {
  auto bytes = build_multi_ink_profile(spec);
  if (!bytes) return std::unexpected(bytes.error());
  std::ofstream f(path, std::ios::binary);
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot create profile file");
  f.write(reinterpret_cast<const char*>(bytes->data()), static_cast<std::streamsize>(bytes->size()));
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot write profile file");
  return {};
}

}  // namespace tp::rip
