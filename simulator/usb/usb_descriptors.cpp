// simulator/usb/usb_descriptors.cpp: descriptors and sysfs description of the emulated printer.
#include "simulator/usb/usb_descriptors.h"

#include <algorithm>
#include <cstdio>

namespace tp::sim {

namespace {

std::string field(const std::string& id, const std::string& key) {
  const std::size_t at = id.find(key + ":");
  if (at == std::string::npos) return {};
  const std::size_t start = at + key.size() + 1;
  const std::size_t end = id.find(';', start);
  return id.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

std::string hex(const std::vector<std::uint8_t>& bytes) {
  std::string s;
  char b[3];
  for (std::uint8_t v : bytes) {
    std::snprintf(b, sizeof b, "%02x", v);
    s += b;
  }
  return s;
}

}  // namespace

UsbIdentity usb_identity(const device::PrinterModel& model) {
  UsbIdentity id;
  id.vendor_id = model.usb_vendor_id;
  id.product_id = model.usb_product_id;
  id.manufacturer = field(model.ieee1284_id, "MFG");
  if (id.manufacturer.empty()) id.manufacturer = "TextilePrint";
  id.product = model.name;
  id.serial = "TPSIM0001";
  id.ieee1284_id = model.ieee1284_id;
  return id;
}

std::vector<std::uint8_t> device_descriptor(const UsbIdentity& id) {
  return {18,   0x01, 0x00, 0x02,  // bLength, DEVICE, bcdUSB 2.00
          0x00, 0x00, 0x00, 64,    // class in interface, max packet 0 = 64
          static_cast<std::uint8_t>(id.vendor_id), static_cast<std::uint8_t>(id.vendor_id >> 8),
          static_cast<std::uint8_t>(id.product_id), static_cast<std::uint8_t>(id.product_id >> 8),
          0x00, 0x01,              // bcdDevice 1.00
          1,    2,    3,    1};    // strings, one configuration
}

std::vector<std::uint8_t> config_descriptor() {
  const std::uint8_t mp_lo = kBulkMaxPacket & 0xFF, mp_hi = kBulkMaxPacket >> 8;
  return {9, 0x02, 32, 0, 1, 1, 0, 0xC0, 1,      // CONFIGURATION: total 32, 1 interface, self-powered
          9, 0x04, 0, 0, 2, 7, 1, 2, 0,          // INTERFACE 0: 2 endpoints, printer, bidirectional
          7, 0x05, kBulkOutEndpoint, 0x02, mp_lo, mp_hi, 0,  // ENDPOINT bulk OUT
          7, 0x05, kBulkInEndpoint, 0x02, mp_lo, mp_hi, 0};  // ENDPOINT bulk IN
}

std::optional<std::vector<std::uint8_t>> string_descriptor(const UsbIdentity& id, std::uint8_t index) {
  if (index == 0) return std::vector<std::uint8_t>{4, 0x03, 0x09, 0x04};  // en-US
  const std::string* s = index == 1 ? &id.manufacturer : index == 2 ? &id.product : index == 3 ? &id.serial : nullptr;
  if (!s) return std::nullopt;
  std::vector<std::uint8_t> d{0, 0x03};
  for (char c : s->substr(0, 126)) {
    d.push_back(static_cast<std::uint8_t>(c));
    d.push_back(0);
  }
  d[0] = static_cast<std::uint8_t>(d.size());
  return d;
}

std::vector<std::uint8_t> device_id_reply(const UsbIdentity& id) {
  const std::size_t n = id.ieee1284_id.size() + 2;
  std::vector<std::uint8_t> r(n);
  r[0] = static_cast<std::uint8_t>(n >> 8);
  r[1] = static_cast<std::uint8_t>(n);
  std::copy(id.ieee1284_id.begin(), id.ieee1284_id.end(), r.begin() + 2);
  return r;
}

std::string umockdev_usb_description(const UsbIdentity& id, int busnum, int devnum, const std::string& syspath) {
  char node[64], ids[64], minor[32];
  std::snprintf(node, sizeof node, "bus/usb/%03d/%03d", busnum, devnum);
  std::snprintf(ids, sizeof ids, "%04x", id.vendor_id);
  const std::string vid = ids;
  std::snprintf(ids, sizeof ids, "%04x", id.product_id);
  const std::string pid = ids;
  std::snprintf(minor, sizeof minor, "189:%d", (busnum - 1) * 128 + devnum - 1);
  std::vector<std::uint8_t> desc = device_descriptor(id);
  const auto cfg = config_descriptor();
  desc.insert(desc.end(), cfg.begin(), cfg.end());
  // Sysfs attribute values end in a newline, as the kernel writes them (libusb warns otherwise).
  std::string s;
  s += "P: " + syspath + "\n";
  s += std::string("N: ") + node + "\n";
  s += "E: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n";
  s += std::string("E: DEVNAME=/dev/") + node + "\n";
  s += "E: BUSNUM=" + std::string(node + 8, 3) + "\nE: DEVNUM=" + std::string(node + 12, 3) + "\n";
  s += "E: ID_VENDOR_ID=" + vid + "\nE: ID_MODEL_ID=" + pid + "\n";
  s += "E: PRODUCT=" + vid + "/" + pid + "/100\n";
  s += "A: busnum=" + std::to_string(busnum) + "\\n\n";
  s += "A: devnum=" + std::to_string(devnum) + "\\n\n";
  s += "A: bConfigurationValue=1\\n\nA: bNumConfigurations=1\\n\nA: bNumInterfaces= 1\\n\n";
  s += "A: speed=480\\n\n";
  s += "A: idVendor=" + vid + "\\n\nA: idProduct=" + pid + "\\n\n";
  s += "A: manufacturer=" + id.manufacturer + "\\n\nA: product=" + id.product + "\\n\nA: serial=" + id.serial + "\\n\n";
  s += std::string("A: dev=") + minor + "\\n\n";
  s += "H: descriptors=" + hex(desc) + "\n";
  return s;
}

}  // namespace tp::sim
