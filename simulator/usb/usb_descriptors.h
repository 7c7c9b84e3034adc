// simulator/usb/usb_descriptors.h: what the emulated printer tells the USB host about itself:
// device, configuration and string descriptors, and the umockdev description of its sysfs node.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "device/model/printer_model.h"

namespace tp::sim {

/// Bulk endpoints of the printer interface.
inline constexpr std::uint8_t kBulkOutEndpoint = 0x01;
inline constexpr std::uint8_t kBulkInEndpoint = 0x82;
inline constexpr std::uint16_t kBulkMaxPacket = 512;  // high speed

struct UsbIdentity {
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  std::string manufacturer;
  std::string product;
  std::string serial;
  std::string ieee1284_id;
};

/// Identity of the emulated device for `model` (manufacturer from the device ID's MFG field).
UsbIdentity usb_identity(const device::PrinterModel& model);

/// The 18-byte device descriptor (USB 2.0, one configuration, strings 1..3).
std::vector<std::uint8_t> device_descriptor(const UsbIdentity& id);
/// Configuration 1: one interface, printer class 7, subclass 1, protocol 2 (bidirectional),
/// bulk OUT 0x01 and bulk IN 0x82 of 512 bytes.
std::vector<std::uint8_t> config_descriptor();
/// String descriptor `index` (0: language IDs, 1 manufacturer, 2 product, 3 serial); nullopt
/// for other indices.
std::optional<std::vector<std::uint8_t>> string_descriptor(const UsbIdentity& id, std::uint8_t index);
/// GET_DEVICE_ID reply: two-byte big-endian length including itself, then the ID.
std::vector<std::uint8_t> device_id_reply(const UsbIdentity& id);

/// umockdev text for the device node /dev/bus/usb/<bus>/<dev> at sysfs `syspath`.
std::string umockdev_usb_description(const UsbIdentity& id, int busnum, int devnum, const std::string& syspath);

}  // namespace tp::sim
