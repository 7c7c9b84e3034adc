// drivers/usb/ieee1284_id.cpp: parsing and matching IEEE 1284 device IDs.
#include "drivers/usb/ieee1284_id.h"

namespace tp::drivers {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\0')) s.remove_suffix(1);
  return s;
}

std::string canonical_key(std::string_view k) {
  if (k == "MANUFACTURER") return "MFG";
  if (k == "MODEL") return "MDL";
  if (k == "COMMAND SET") return "CMD";
  if (k == "CLASS") return "CLS";
  return std::string(k);
}

}  // namespace

std::map<std::string, std::string> parse_ieee1284_id(std::string_view id) {
  std::map<std::string, std::string> out;
  while (!id.empty()) {
    const std::size_t semi = id.find(';');
    std::string_view field = id.substr(0, semi);
    id = semi == std::string_view::npos ? std::string_view{} : id.substr(semi + 1);
    const std::size_t colon = field.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string key = canonical_key(trim(field.substr(0, colon)));
    if (key.empty()) continue;
    out[key] = std::string(trim(field.substr(colon + 1)));
  }
  return out;
}

bool ieee1284_matches(std::string_view id, std::string_view pattern) {
  const auto have = parse_ieee1284_id(id);
  for (const auto& [key, want] : parse_ieee1284_id(pattern)) {
    auto it = have.find(key);
    if (it == have.end()) return false;
    if (key == "CMD") {
      // Command sets are a comma-separated list: the wanted one must be among them.
      bool found = false;
      std::string_view sets = it->second;
      while (!sets.empty() && !found) {
        const std::size_t comma = sets.find(',');
        found = trim(sets.substr(0, comma)) == want;
        sets = comma == std::string_view::npos ? std::string_view{} : sets.substr(comma + 1);
      }
      if (!found) return false;
    } else if (it->second != want) {
      return false;
    }
  }
  return true;
}

}  // namespace tp::drivers
