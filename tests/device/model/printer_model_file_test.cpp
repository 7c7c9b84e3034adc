// tests/device/model/printer_model_file_test.cpp: printer model files round-trip, and every kind
// of mistake is reported with file, line and key.
#include "device/model/printer_model_file.h"

#include <gtest/gtest.h>

namespace tp::device {
namespace {

constexpr const char* kGood = R"(# A six-ink printer for lab tests
tp-printer-model 1
name = lab-6c
usb_vendor_id = 0x1234
usb_product_id = 0x00ab
ieee1284_id = MFG:Lab;MDL:LAB-6C;CMD:TPWP;CLS:PRINTER;
dpi_x = 720
dpi_y = 1440
nozzles_per_ink = 360
nozzle_pitch_rows = 4
bits_per_pixel = 2
print_width_mm = 1800.5
swath_buffer_bytes = 33554432
swath_buffer_slots = 6
carriage_speed_mm_s = 1200
feed_speed_mm_s = 150
protocol_version = 1
ink = cyan 0
ink = magenta 12.7
ink = yellow 25.4
ink = black 38.1
ink = light_cyan 50.8
ink = light_magenta 63.5
)";

TEST(PrinterModelFile, ParsesEveryField) {
  auto m = parse_printer_model(kGood, "lab.tpm");
  ASSERT_TRUE(m) << m.error().message;
  EXPECT_EQ(m->name, "lab-6c");
  EXPECT_EQ(m->usb_vendor_id, 0x1234);
  EXPECT_EQ(m->dpi_y, 1440);
  EXPECT_EQ(m->nozzle_pitch_rows, 4);
  EXPECT_DOUBLE_EQ(m->print_width_mm, 1800.5);
  ASSERT_EQ(m->inks.size(), 6u);
  EXPECT_EQ(m->inks[4].name, "light_cyan");
  EXPECT_DOUBLE_EQ(m->inks[1].head_offset_x_mm, 12.7);
  EXPECT_EQ(m->ieee1284_id, "MFG:Lab;MDL:LAB-6C;CMD:TPWP;CLS:PRINTER;");
}

TEST(PrinterModelFile, FormatThenParseIsIdentity) {
  auto m = parse_printer_model(kGood, "lab.tpm");
  ASSERT_TRUE(m);
  auto again = parse_printer_model(format_printer_model(*m), "formatted");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(format_printer_model(*again), format_printer_model(*m));
  EXPECT_DOUBLE_EQ(again->inks[3].head_offset_x_mm, 38.1);
  // The built-in model is expressible too.
  auto builtin = parse_printer_model(format_printer_model(PrinterModel{}), "builtin");
  ASSERT_TRUE(builtin) << builtin.error().message;
  EXPECT_EQ(builtin->name, "tp-sim-1600");
}

TEST(PrinterModelFile, ColourFieldsParseAndRoundTrip) {
  constexpr const char* text =
      "tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = cyan\nink = black\nfabric = silk\n"
      "yule_nielsen_n = 2.4\ndrop_coverage = 0.4 0.7 0.95\nink_strength = black 1.2\n";
  auto m = parse_printer_model(text, "c.tpm");
  ASSERT_TRUE(m) << m.error().message;
  EXPECT_EQ(m->fabric, "silk");
  EXPECT_DOUBLE_EQ(m->yule_nielsen_n, 2.4);
  EXPECT_EQ(m->drop_coverage, (std::vector<double>{0.4, 0.7, 0.95}));
  EXPECT_DOUBLE_EQ(m->inks[1].strength, 1.2);
  EXPECT_DOUBLE_EQ(m->inks[0].strength, 1.0);
  auto again = parse_printer_model(format_printer_model(*m), "formatted");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(format_printer_model(*again), format_printer_model(*m));
  const char* bad[][2] = {
      {"fabric = denim\n", "key 'fabric': expected a fabric preset"},
      {"ink_strength = magenta 2\n", "key 'ink_strength': no ink 'magenta'"},
      {"drop_coverage = 0.5 1\n", "drop_coverage: needs one coverage per drop level (3), got 2"},
      {"yule_nielsen_n = 0.5\n", "key 'yule_nielsen_n': expected 0 (the fabric's) or a number in 1..10"},
  };
  for (const auto& b : bad) {
    auto r = parse_printer_model(std::string("tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = cyan\n") + b[0], "c.tpm");
    ASSERT_FALSE(r) << b[0];
    EXPECT_NE(r.error().message.find(b[1]), std::string::npos) << r.error().message;
  }
}

struct Bad {
  const char* text;
  const char* expect;
};

TEST(PrinterModelFile, ErrorsNameFileLineAndKey) {
  const Bad cases[] = {
      {"name = x\n", "lab.tpm:1: expected the header line"},
      {"", "lab.tpm: empty"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = cyan\nspeed = 3\n", "lab.tpm:6: unknown key 'speed'"},
      {"tp-printer-model 1\nname = x\ndpi_x = fast\n", "lab.tpm:3: key 'dpi_x': expected an integer in 50..4800, got 'fast'"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_x = 300\n", "lab.tpm:4: key 'dpi_x' given twice"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\nbits_per_pixel = 3\n", "lab.tpm:4: key 'bits_per_pixel': expected 1, 2, 4 or 8"},
      {"tp-printer-model 1\nname = x\nno equals sign\n", "lab.tpm:3: expected 'key = value'"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\n", "no 'ink' lines"},
      {"tp-printer-model 1\ndpi_x = 600\ndpi_y = 600\nink = cyan\n", "required key 'name' missing"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = Cyan!\n", "lab.tpm:5: key 'ink'"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = cyan\nink = cyan 3\n", "'cyan' listed twice"},
      {"tp-printer-model 1\nname = x\ndpi_x = 600\ndpi_y = 600\nink = cyan nan\n", "head offset"},
      {"tp-printer-model 1\nname = x\nusb_vendor_id = 0x10000\n", "expected an integer in 0..0xffff"},
  };
  for (const auto& c : cases) {
    auto m = parse_printer_model(c.text, "lab.tpm");
    ASSERT_FALSE(m) << c.text;
    EXPECT_EQ(m.error().code, ErrorCode::kParse);
    EXPECT_NE(m.error().message.find(c.expect), std::string::npos) << "got: " << m.error().message;
  }
}

TEST(PrinterModelFile, MissingFileIsNamed) {
  auto m = load_printer_model("/nonexistent/dir/model.tpm");
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().message.find("/nonexistent/dir/model.tpm"), std::string::npos);
}

}  // namespace
}  // namespace tp::device
