// tests/host/job/design_limits_test.cpp: oversized jobs are refused before they run, naming the limit.
#include "host/job/design_limits.h"

#include <gtest/gtest.h>

#include <fstream>

#include "host/job/manifest.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

const std::string kHead = R"({"format": "tp-job/1", "name": "big", "garment": {"pattern": "pattern.json"},
  "marker": {"fabric_width": "1.5 m"}, "design": {"layers": [)";

Result<Job> load(const fs::path& dir, const std::string& text, const PackageLimits& limits = {}) {
  std::ofstream(dir / "pattern.json") << "{}";
  std::ofstream(dir / "job.json") << text;
  auto pkg = JobPackage::open(dir, dir / "unused", limits);
  if (!pkg) return std::unexpected(pkg.error());
  return load_job(*pkg);
}

TEST(DesignLimits, LongStrokeIsRefusedNamingTheLimit) {
  std::string pts;
  for (int i = 0; i < 25000; ++i) pts += std::string(i ? "," : "") + "[" + std::to_string(i) + ",0,0]";
  auto job = load(tp::test::scratch_dir("limits-stroke"),
                  kHead + R"({"type": "stroke", "radius": 5, "points": [)" + pts + "]}]}}");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("/design/layers/0/points"), std::string::npos) << job.error().message;
  EXPECT_NE(job.error().message.find("25000"), std::string::npos);
  EXPECT_NE(job.error().message.find("--limit max_stroke_points=N"), std::string::npos);
  // Raised, the same job passes.
  PackageLimits raised;
  raised.max_stroke_points = 30000;
  EXPECT_TRUE(load(tp::test::scratch_dir("limits-stroke-ok"),
                   kHead + R"({"type": "stroke", "radius": 5, "points": [)" + pts + "]}]}}", raised));
}

TEST(DesignLimits, ManyHugeLayersAreRefusedForLayersPixelsAndMemory) {
  std::string layers;
  for (int i = 0; i < 40; ++i)
    layers += std::string(i ? "," : "") +
              R"({"type": "planar", "procedural": {"kind": "marbling", "size_px": 16384}, "centre": [0,0,0], "width": 100})";
  auto job = load(tp::test::scratch_dir("limits-layers"), kHead + layers + "]}}");
  ASSERT_FALSE(job);
  const std::string& m = job.error().message;
  EXPECT_NE(m.find("max_layers"), std::string::npos) << m;
  EXPECT_NE(m.find("max_source_pixels"), std::string::npos) << m;
  EXPECT_NE(m.find("max_memory_bytes"), std::string::npos) << m;
}

TEST(DesignLimits, PngSizeIsReadFromItsHeader) {
  fs::path dir = tp::test::scratch_dir("limits-png");
  // A PNG signature and IHDR claiming 100000 x 100000 pixels; nothing is decoded.
  const unsigned char head[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                0, 1, 0x86, 0xA0, 0, 1, 0x86, 0xA0, 8, 6, 0, 0, 0};
  std::ofstream(dir / "huge.png", std::ios::binary).write(reinterpret_cast<const char*>(head), sizeof head);
  auto job = load(dir, kHead + R"({"type": "planar", "image": "huge.png", "centre": [0,0,0], "width": 100}]}})");
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("10000000000"), std::string::npos) << job.error().message;
}

TEST(DesignLimits, ManifestAndAssetSizesAreCheckedBeforeReading) {
  fs::path dir = tp::test::scratch_dir("limits-manifest");
  std::ofstream(dir / "pattern.json") << "{}";
  {
    std::ofstream f(dir / "job.json");
    f << "{\"pad\": \"";
  }
  fs::resize_file(dir / "job.json", 64u << 20);  // sparse: reading it would cost 64 MiB
  auto pkg = JobPackage::open(dir, dir / "unused");
  ASSERT_TRUE(pkg);
  auto job = load_job(*pkg);
  ASSERT_FALSE(job);
  EXPECT_NE(job.error().message.find("max_manifest_bytes"), std::string::npos) << job.error().message;

  PackageLimits small;
  small.max_asset_bytes = 1;
  auto j2 = load(tp::test::scratch_dir("limits-asset"), kHead + "]}}", small);
  ASSERT_FALSE(j2);
  EXPECT_NE(j2.error().message.find("max_asset_bytes"), std::string::npos) << j2.error().message;
}

}  // namespace
}  // namespace tp::host
