// host/job/copy_text.h: a text layer's template ("{name} {number}") filled from an order's copy.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tp::host {

using CopyFields = std::vector<std::pair<std::string, std::string>>;

/// The field names a template uses, in order of first use ("{name}" -> "name"; "{{" is a brace).
[[nodiscard]] std::vector<std::string> template_fields(const std::string& text);

/// `text` with each {field} replaced by the copy's value. A field the copy lacks is left out and
/// its name appended to `missing` (if given), so a caller can name it.
[[nodiscard]] std::string fill_template(const std::string& text, const CopyFields& copy,
                                        std::vector<std::string>* missing = nullptr);

}  // namespace tp::host
