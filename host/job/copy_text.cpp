// host/job/copy_text.cpp: {field} templates of text layers, filled per copy of an order.
#include "host/job/copy_text.h"

#include <algorithm>

namespace tp::host {

namespace {

// Walks `text`, calling `literal(c)` for plain characters and `field(name)` for each {name}.
template <class L, class F>
void walk(const std::string& text, L literal, F field) {
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if ((c == '{' || c == '}') && i + 1 < text.size() && text[i + 1] == c) {
      literal(c);
      ++i;
    } else if (c == '{') {
      const size_t end = text.find('}', i + 1);
      if (end == std::string::npos) {
        literal(c);
        continue;
      }
      field(text.substr(i + 1, end - i - 1));
      i = end;
    } else {
      literal(c);
    }
  }
}

}  // namespace

std::vector<std::string> template_fields(const std::string& text) {
  std::vector<std::string> out;
  walk(
      text, [](char) {},
      [&](const std::string& f) {
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
      });
  return out;
}

std::string fill_template(const std::string& text, const CopyFields& copy, std::vector<std::string>* missing) {
  std::string out;
  walk(
      text, [&](char c) { out += c; },
      [&](const std::string& f) {
        auto it = std::find_if(copy.begin(), copy.end(), [&](const auto& kv) { return kv.first == f; });
        if (it != copy.end())
          out += it->second;
        else if (missing)
          missing->push_back(f);
      });
  return out;
}

}  // namespace tp::host
