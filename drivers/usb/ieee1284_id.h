// drivers/usb/ieee1284_id.h: the IEEE 1284 device ID a USB printer returns to GET_DEVICE_ID
// ("MFG:Acme;MDL:TP-1600;CMD:TPWP;CLS:PRINTER;"), parsed into its fields.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace tp::drivers {

/// Fields of a device ID by key. Keys are kept as written; the long and short spellings of the
/// standard keys are unified (MANUFACTURER -> MFG, MODEL -> MDL, COMMAND SET -> CMD,
/// CLASS -> CLS). Malformed pieces (no ':') are skipped.
std::map<std::string, std::string> parse_ieee1284_id(std::string_view id);

/// True if every "KEY:value" pair of `pattern` (same syntax) is in `id`; for CMD the value may be
/// one of the comma-separated command sets. An empty pattern matches any ID.
bool ieee1284_matches(std::string_view id, std::string_view pattern);

}  // namespace tp::drivers
