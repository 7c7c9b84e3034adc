// host/common/text.h: untrusted text made safe for JSON and logs (file names, DXF strings).
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace tp::host {

/// True when `s` is well-formed UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF).
bool is_valid_utf8(std::string_view s);

/// `s` with every byte that is not part of a well-formed UTF-8 sequence written as "\xNN", so a
/// file name such as "caf\xE9.zip" (Latin-1) stays recognisable and is valid UTF-8.
std::string printable_utf8(std::string_view s);

/// nlohmann's dump that never throws on text that is not UTF-8 (invalid bytes become U+FFFD).
std::string dump_json(const nlohmann::json& j, int indent = -1);

}  // namespace tp::host
