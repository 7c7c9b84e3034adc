// geometry/pattern/role.cpp: role keywords found in piece names of common pattern sources.
#include "geometry/pattern/role.h"

#include <cctype>
#include <vector>

namespace tp::geometry {
namespace {

/// Splits "frontSideDart", "left_ftorso", "Back Bodice", "sleeve2" into lower-case words.
std::vector<std::string> words(std::string_view s) {
  std::vector<std::string> out;
  std::string cur;
  auto flush = [&] {
    if (!cur.empty()) out.push_back(cur);
    cur.clear();
  };
  for (size_t i = 0; i < s.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (!std::isalpha(c)) {
      flush();
      continue;
    }
    // A capital after a lower-case letter starts a new word (camelCase).
    if (std::isupper(c) && i > 0 && std::islower(static_cast<unsigned char>(s[i - 1]))) flush();
    cur += static_cast<char>(std::tolower(c));
  }
  flush();
  return out;
}

}  // namespace

std::string guess_role(std::string_view piece_name) {
  auto ws = words(piece_name);
  // Specific garment parts first: a "front sleeve" is a sleeve.
  struct Key { const char* word; const char* role; };
  static const Key specific[] = {
      {"sleeve", "sleeve"}, {"hood", "hood"}, {"collar", "collar"}, {"cuff", "cuff"}, {"waistband", "waistband"},
      {"wb", "waistband"},  {"pocket", "pocket"}};
  for (const auto& w : ws)
    for (const Key& k : specific)
      if (w == k.word || w == std::string(k.word) + "s")
        return k.role;
  static const Key sides[] = {{"front", "front"}, {"ftorso", "front"}, {"f", "front"},
                              {"back", "back"},   {"btorso", "back"},  {"b", "back"}};
  for (const auto& w : ws)
    for (const Key& k : sides)
      if (w == k.word) return k.role;
  return "";
}

}  // namespace tp::geometry
