// tests/host/job/order_manifest_test.cpp: job.json "order" and text layers: parsed, and broken
// orders rejected naming the size, the file and the JSON pointer.
#include <gtest/gtest.h>

#include <fstream>

#include "host/job/copy_text.h"
#include "host/job/manifest.h"
#include "tests/support/paths.h"

namespace tp::host {
namespace {

namespace fs = std::filesystem;

class OrderManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = tp::test::scratch_dir("order-manifest");
    for (const char* f : {"s.json", "m.json", "l.json"}) std::ofstream(dir_ / f) << "{}";
  }
  Result<Job> load(const std::string& order, const std::string& garment = R"({"sample": "simple_top", "size": "M"})",
                   const std::string& layers = "[]") {
    std::ofstream(dir_ / "job.json") << R"({"format": "tp-job/1", "name": "kit", "garment": )" << garment
                                     << R"(, "design": {"layers": )" << layers
                                     << R"(}, "marker": {"fabric_width": "1.5 m"})"
                                     << (order.empty() ? "" : ", \"order\": " + order) << "}";
    auto pkg = JobPackage::open(dir_, dir_ / "unused");
    if (!pkg) return std::unexpected(pkg.error());
    return load_job(*pkg);
  }
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  fs::path dir_;
};

const char* kText = R"([{"type": "text", "name": "name", "text": "{name} {number}", "size": "4 cm",
  "centre": [0, 1200, -200], "normal": [0, 0, -1], "colour": [250, 250, 250, 255], "outline": "2 mm"}])";

TEST_F(OrderManifestTest, AJobWithoutAnOrderHasNone) {
  auto job = load("");
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_FALSE(job->order);
}

TEST_F(OrderManifestTest, SizesQuantitiesAndCopiesAreRead) {
  auto job = load(R"({"sizes": [{"size": "S", "quantity": 1}, {"size": "M", "quantity": 2}], "placement": "graded",
    "copies": [{"name": "ANNA", "number": 7}, {"name": "BEN", "number": "10"}, {"name": "CY", "number": 3}]})",
                  R"({"sample": "simple_top", "size": "M"})", kText);
  ASSERT_TRUE(job) << job.error().message;
  ASSERT_TRUE(job->order);
  EXPECT_EQ(job->order->placement, "graded");
  EXPECT_EQ(job->order->base_size, "M");
  EXPECT_EQ(job->order->garments(), 3);
  ASSERT_EQ(job->order->copies.size(), 3u);
  EXPECT_EQ(fill_template(job->design[0].text, job->order->copies[0]), "ANNA 7");
  EXPECT_EQ(fill_template(job->design[0].text, job->order->copies[1]), "BEN 10");
  EXPECT_DOUBLE_EQ(job->design[0].text_size_mm, 40);
  EXPECT_DOUBLE_EQ(job->design[0].outline_mm, 2);
}

TEST_F(OrderManifestTest, CopiesComeFromACsvAsset) {
  write("copies.csv", "name,number\nANNA,7\n\"O'NEIL, JR\",10\n");
  auto job = load(R"({"sizes": [{"size": "L", "quantity": 2}], "copies_csv": "copies.csv"})",
                  R"({"sample": "simple_top", "size": "M"})", kText);
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->order->base_size, "L");  // the job's size is not ordered: the first size is the base
  ASSERT_EQ(job->order->copies.size(), 2u);
  EXPECT_EQ(fill_template("{name}", job->order->copies[1]), "O'NEIL, JR");
}

TEST_F(OrderManifestTest, BrokenOrdersNameTheSizeAndPointer) {
  auto bad = load(
      R"({"sizes": [{"size": "XXL", "quantity": 1}, {"size": "M", "quantity": 0}, {"size": "M", "quantity": 1}]})");
  ASSERT_FALSE(bad);
  const std::string& m = bad.error().message;
  EXPECT_NE(m.find("job.json: /order/sizes/0/size: size 'XXL'"), std::string::npos) << m;
  EXPECT_NE(m.find("job.json: /order/sizes/1/quantity"), std::string::npos) << m;
  EXPECT_NE(m.find("job.json: /order/sizes/2/size: size 'M' is listed twice"), std::string::npos) << m;

  bad = load(R"({"sizes": [{"size": "S", "quantity": 2}], "copies": [{"name": "ANNA"}]})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/order/copies: 1 copies for 2 garments"), std::string::npos)
      << bad.error().message;

  bad = load(R"({"sizes": [{"size": "S", "quantity": 1}], "base_size": "L", "placement": "sideways"})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/order/base_size: base size 'L' is not one of"), std::string::npos);
  EXPECT_NE(bad.error().message.find("/order/placement"), std::string::npos);

  // A text field no copy has, and text fields without any order.
  bad = load(R"({"sizes": [{"size": "S", "quantity": 1}], "copies": [{"name": "ANNA"}]})",
             R"({"sample": "simple_top", "size": "M"})", kText);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/design/layers/0/text: copy 1 has no field 'number'"), std::string::npos)
      << bad.error().message;
  bad = load("", R"({"sample": "simple_top", "size": "M"})", kText);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/design/layers/0/text: '{name} {number}' takes {name}"), std::string::npos);
}

TEST_F(OrderManifestTest, ACsvProblemNamesTheFileAndLine) {
  write("copies.csv", "name,number\nANNA,7\nBEN\n");
  auto bad = load(R"({"sizes": [{"size": "S", "quantity": 2}], "copies_csv": "copies.csv"})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("job.json: /order/copies_csv: copies.csv: line 3: 1 fields, the header has 2"),
            std::string::npos)
      << bad.error().message;
  bad = load(R"({"sizes": [{"size": "S", "quantity": 1}], "copies_csv": "missing.csv"})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/order/copies_csv"), std::string::npos);
}

TEST_F(OrderManifestTest, ImportedPatternsNeedAPatternAndBodyPerSize) {
  const std::string garment = R"({"pattern": "m.json", "size": "M", "body": {"dress_form": {"bust": "92 cm"}}})";
  auto job = load(R"({"sizes": [
      {"size": "S", "quantity": 1, "pattern": "s.json", "body": {"dress_form": {"bust": "86 cm", "waist": "68 cm"}}},
      {"size": "M", "quantity": 1, "pattern": "m.json", "body": {"dress_form": {"bust": "92 cm"}}}]})",
                  garment);
  ASSERT_TRUE(job) << job.error().message;
  EXPECT_EQ(job->order->sizes[0].pattern->filename(), "s.json");
  ASSERT_EQ(job->order->sizes[0].dress_form_mm.size(), 2u);
  EXPECT_DOUBLE_EQ(job->order->sizes[0].dress_form_mm[0].second, 860);

  auto bad = load(R"({"sizes": [{"size": "L", "quantity": 1, "pattern": "nope.json"},
                                {"size": "M", "quantity": 1, "body": {"dress_form": {"bust": "92 cm"}}}]})",
                  garment);
  ASSERT_FALSE(bad);
  const std::string& m = bad.error().message;
  EXPECT_NE(m.find("/order/sizes/0/pattern"), std::string::npos) << m;
  EXPECT_NE(m.find("nope.json"), std::string::npos) << m;
  EXPECT_NE(m.find("/order/sizes/0: size 'L': the job's body is a dress form"), std::string::npos) << m;
  EXPECT_NE(m.find("/order/sizes/1/pattern"), std::string::npos) << m;
}

TEST_F(OrderManifestTest, APerGarmentMarkerBudgetGrowsWithTheGarments) {
  const std::string sizes = R"("sizes": [{"size": "S", "quantity": 2}, {"size": "M", "quantity": 4}])";
  auto whole = load("{" + sizes + "}");
  ASSERT_TRUE(whole) << whole.error().message;
  EXPECT_EQ(whole->order->marker_budget, "order");
  EXPECT_EQ(whole->marker.iterations, 20000);  // the job's default, for the order's one marker
  auto per = load("{" + sizes + R"(, "marker_budget": "per_garment"})");
  ASSERT_TRUE(per) << per.error().message;
  EXPECT_EQ(per->marker.iterations, 6 * 20000);
  auto bad = load("{" + sizes + R"(, "marker_budget": "per_piece"})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("/order/marker_budget"), std::string::npos) << bad.error().message;
}

TEST_F(OrderManifestTest, AnImportedPatternOnABodyMeshIsRefusedSayingWhy) {
  write("body.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string garment = R"({"pattern": "m.json", "size": "M", "body": {"mesh": "body.obj"}})";
  auto bad = load(R"({"sizes": [{"size": "S", "quantity": 1, "pattern": "s.json"},
                                {"size": "M", "quantity": 1, "pattern": "m.json"}]})",
                  garment);
  ASSERT_FALSE(bad);
  const std::string& m = bad.error().message;
  EXPECT_NE(m.find("/order/sizes/0: size 'S': orders of an imported pattern take a dress form per size"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("landmarks"), std::string::npos) << m;
  EXPECT_NE(m.find("/order/sizes/1: size 'M'"), std::string::npos) << m;
}

}  // namespace
}  // namespace tp::host
