// host/daemon/http/validation_list.h: a package's validation error as the JSON list the HTTP API
// answers with (status 422): one entry per problem with its file and JSON pointer.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace tp::host {

/// Splits a validation message (lines "job.json: /print/dpi: must be ...", as `printctl validate`
/// prints them) into [{"file","pointer","message"}]. A line without a pointer gets pointer "";
/// a line without a file gets file "".
nlohmann::json validation_list(const std::string& message);

}  // namespace tp::host
