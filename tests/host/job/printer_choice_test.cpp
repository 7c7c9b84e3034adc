// tests/host/job/printer_choice_test.cpp: the printer choice's names parse back, a run's override
// wins over the job's own printer, and the manifest reads "usb" as the USB printer.
#include "host/job/printer_choice.h"

#include <gtest/gtest.h>

namespace tp::host {
namespace {

TEST(PrinterChoice, NamesParseBackAndNothingElseParses) {
  for (const std::string& name : printer_choice_names()) {
    auto c = parse_printer_choice(name);
    ASSERT_TRUE(c) << name;
    EXPECT_EQ(to_string(*c), name);
  }
  EXPECT_EQ(printer_choice_names(), (std::vector<std::string>{"sim", "usb", "none"}));
  EXPECT_FALSE(parse_printer_choice("SIM"));
  EXPECT_FALSE(parse_printer_choice(""));
}

TEST(PrinterChoice, TheOverrideWinsOverTheJobsPrinter) {
  EXPECT_EQ(effective_printer(PrinterChoice::kSim, std::nullopt), PrinterChoice::kSim);
  EXPECT_EQ(effective_printer(PrinterChoice::kSim, PrinterChoice::kNone), PrinterChoice::kNone);
  EXPECT_EQ(effective_printer(PrinterChoice::kUsb, PrinterChoice::kSim), PrinterChoice::kSim);
}

TEST(PrinterChoice, OnlyTheSimulatedPrinterNeedsPrintsim) {
  // ctest does not run this binary under printsim.
  EXPECT_TRUE(needs_printsim(PrinterChoice::kSim));
  EXPECT_FALSE(needs_printsim(PrinterChoice::kUsb));
  EXPECT_FALSE(needs_printsim(PrinterChoice::kNone));
}

}  // namespace
}  // namespace tp::host
