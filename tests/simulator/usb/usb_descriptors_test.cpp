// tests/simulator/usb/usb_descriptors_test.cpp: the emulated printer's descriptors, byte for byte
// where the USB and printer class specifications fix them.
#include "simulator/usb/usb_descriptors.h"

#include <gtest/gtest.h>

namespace tp::sim {
namespace {

TEST(UsbDescriptors, DescribeABidirectionalPrinterInterface) {
  const auto id = usb_identity(device::PrinterModel{});
  const auto dev = device_descriptor(id);
  ASSERT_EQ(dev.size(), 18u);
  EXPECT_EQ(dev[1], 0x01);
  EXPECT_EQ(dev[8] | dev[9] << 8, 0x1d6b);
  EXPECT_EQ(dev[10] | dev[11] << 8, 0x0104);
  const auto cfg = config_descriptor();
  ASSERT_EQ(cfg.size(), 32u);
  EXPECT_EQ(cfg[2], 32);  // wTotalLength
  EXPECT_EQ(cfg[9 + 5], 7) << "interface class: printer";
  EXPECT_EQ(cfg[9 + 6], 1) << "subclass: printers";
  EXPECT_EQ(cfg[9 + 7], 2) << "protocol: bidirectional";
  EXPECT_EQ(cfg[18 + 2], kBulkOutEndpoint);
  EXPECT_EQ(cfg[25 + 2], kBulkInEndpoint);
  EXPECT_EQ(cfg[18 + 4] | cfg[18 + 5] << 8, 512);
}

TEST(UsbDescriptors, DeviceIdReplyHasABigEndianLengthIncludingItself) {
  UsbIdentity id;
  id.ieee1284_id = "MFG:A;MDL:B;";
  const auto r = device_id_reply(id);
  ASSERT_EQ(r.size(), 14u);
  EXPECT_EQ(r[0], 0);
  EXPECT_EQ(r[1], 14);
  EXPECT_EQ(std::string(r.begin() + 2, r.end()), "MFG:A;MDL:B;");
}

TEST(UsbDescriptors, StringsAreUtf16WithLanguageZero) {
  UsbIdentity id;
  id.product = "TP";
  EXPECT_EQ(*string_descriptor(id, 0), (std::vector<std::uint8_t>{4, 3, 0x09, 0x04}));
  EXPECT_EQ(*string_descriptor(id, 2), (std::vector<std::uint8_t>{6, 3, 'T', 0, 'P', 0}));
  EXPECT_FALSE(string_descriptor(id, 9));
  EXPECT_EQ(usb_identity(device::PrinterModel{}).manufacturer, "TextilePrint");
}

TEST(UsbDescriptors, SysfsDescriptionCarriesBusDeviceAndDescriptors) {
  const auto text = umockdev_usb_description(usb_identity(device::PrinterModel{}), 1, 7, "/devices/x/usb1/1-1");
  EXPECT_NE(text.find("N: bus/usb/001/007\n"), std::string::npos) << text;
  EXPECT_NE(text.find("A: devnum=7\\n\n"), std::string::npos);
  EXPECT_NE(text.find("H: descriptors=12010002"), std::string::npos);
  EXPECT_NE(text.find("E: DEVNAME=/dev/bus/usb/001/007\n"), std::string::npos);
}

}  // namespace
}  // namespace tp::sim
