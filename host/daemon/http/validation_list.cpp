// host/daemon/http/validation_list.cpp: parsing "file: /pointer: what" lines into JSON entries.
#include "host/daemon/http/validation_list.h"

namespace tp::host {

nlohmann::json validation_list(const std::string& message) {
  nlohmann::json out = nlohmann::json::array();
  size_t start = 0;
  while (start < message.size()) {
    size_t nl = message.find('\n', start);
    if (nl == std::string::npos) nl = message.size();
    const std::string line = message.substr(start, nl - start);
    start = nl + 1;
    if (line.empty()) continue;
    nlohmann::json e = {{"file", ""}, {"pointer", ""}, {"message", line}};
    // "<file>: <pointer>: <what>": a file part has no spaces; a pointer starts with '/'.
    const size_t c1 = line.find(": ");
    if (c1 != std::string::npos && line.substr(0, c1).find(' ') == std::string::npos) {
      e["file"] = line.substr(0, c1);
      std::string rest = line.substr(c1 + 2);
      const size_t c2 = rest.find(": ");
      if (!rest.empty() && rest.front() == '/' && c2 != std::string::npos) {
        e["pointer"] = rest.substr(0, c2) == "/" ? "" : rest.substr(0, c2);
        rest = rest.substr(c2 + 2);
      }
      e["message"] = rest;
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace tp::host
