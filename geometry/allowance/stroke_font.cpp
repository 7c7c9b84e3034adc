// geometry/allowance/stroke_font.cpp: glyphs on a 4 x 6 grid (cap height 6 units, advance 6).
#include "geometry/allowance/stroke_font.h"

#include <array>
#include <cctype>
#include <cstdlib>
#include <string>

namespace tp::geometry {
namespace {

constexpr double kCapUnits = 6.0;      // grid units of the capital height
constexpr double kAdvanceUnits = 6.0;  // glyph width 4 plus a gap of 2

// Each glyph: polylines separated by '|', points "x,y" separated by spaces, in grid units.
struct Glyph {
  char c;
  const char* strokes;
};
constexpr Glyph kGlyphs[] = {
    {'A', "0,0 0,4 2,6 4,4 4,0|0,3 4,3"},
    {'B', "0,0 0,6 3,6 4,5 4,4 3,3 0,3|3,3 4,2 4,1 3,0 0,0"},
    {'C', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1"},
    {'D', "0,0 0,6 2,6 4,4 4,2 2,0 0,0"},
    {'E', "4,6 0,6 0,0 4,0|0,3 3,3"},
    {'F', "4,6 0,6 0,0|0,3 3,3"},
    {'G', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,3 2,3"},
    {'H', "0,0 0,6|4,0 4,6|0,3 4,3"},
    {'I', "1,6 3,6|2,6 2,0|1,0 3,0"},
    {'J', "1,6 4,6|3,6 3,1 2,0 1,0 0,1"},
    {'K', "0,0 0,6|4,6 0,2|1,3 4,0"},
    {'L', "0,6 0,0 4,0"},
    {'M', "0,0 0,6 2,3 4,6 4,0"},
    {'N', "0,0 0,6 4,0 4,6"},
    {'O', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0"},
    {'P', "0,0 0,6 3,6 4,5 4,4 3,3 0,3"},
    {'Q', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0|2,2 4,0"},
    {'R', "0,0 0,6 3,6 4,5 4,4 3,3 0,3|2,3 4,0"},
    {'S', "4,5 3,6 1,6 0,5 0,4 1,3 3,3 4,2 4,1 3,0 1,0 0,1"},
    {'T', "0,6 4,6|2,6 2,0"},
    {'U', "0,6 0,1 1,0 3,0 4,1 4,6"},
    {'V', "0,6 2,0 4,6"},
    {'W', "0,6 1,0 2,4 3,0 4,6"},
    {'X', "0,0 4,6|0,6 4,0"},
    {'Y', "0,6 2,3 4,6|2,3 2,0"},
    {'Z', "0,6 4,6 0,0 4,0"},
    {'0', "1,0 0,1 0,5 1,6 3,6 4,5 4,1 3,0 1,0|1,1 3,5"},
    {'1', "1,5 2,6 2,0|1,0 3,0"},
    {'2', "0,5 1,6 3,6 4,5 4,4 0,0 4,0"},
    {'3', "0,5 1,6 3,6 4,5 4,4 3,3 1,3|3,3 4,2 4,1 3,0 1,0 0,1"},
    {'4', "3,0 3,6 0,2 4,2"},
    {'5', "4,6 0,6 0,3 3,3 4,2 4,1 3,0 1,0 0,1"},
    {'6', "4,5 3,6 1,6 0,5 0,1 1,0 3,0 4,1 4,2 3,3 0,3"},
    {'7', "0,6 4,6 1,0"},
    {'8', "1,3 0,4 0,5 1,6 3,6 4,5 4,4 3,3 1,3 0,2 0,1 1,0 3,0 4,1 4,2 3,3"},
    {'9', "4,3 1,3 0,4 0,5 1,6 3,6 4,5 4,1 3,0 1,0 0,1"},
    {'-', "1,3 3,3"},
    {'.', "2,0 2,0.4"},
    {',', "2,0.4 1.5,-1"},
    {'/', "0,0 4,6"},
    {':', "2,1 2,1.4|2,4 2,4.4"},
    {'_', "0,0 4,0"},
    {'(', "3,6 2,5 1.5,3 2,1 3,0"},
    {')', "1,6 2,5 2.5,3 2,1 1,0"},
    {'+', "2,1 2,5|0,3 4,3"},
    {'=', "0,2 4,2|0,4 4,4"},
    {'#', "1,0 1,6|3,0 3,6|0,2 4,2|0,4 4,4"},
    {'\'', "2,6 2,4.5"},
    {'?', "0,5 1,6 3,6 4,5 4,4 2,3 2,2|2,0 2,0.4"},
    {'<', "4,5 0,3 4,1"},
    {'>', "0,5 4,3 0,1"},
    {'*', "2,1 2,5|0.5,2 3.5,4|0.5,4 3.5,2"},
};

const Glyph* find_glyph(char c) {
  const char u = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const Glyph& g : kGlyphs)
    if (g.c == u) return &g;
  return nullptr;
}

std::vector<std::vector<Vec2>> parse(const char* s) {
  std::vector<std::vector<Vec2>> out(1);
  const std::string str(s);
  size_t i = 0;
  while (i < str.size()) {
    if (str[i] == '|') {
      out.emplace_back();
      ++i;
      continue;
    }
    if (str[i] == ' ') {
      ++i;
      continue;
    }
    char* end = nullptr;
    const double x = std::strtod(str.c_str() + i, &end);
    const double y = std::strtod(end + 1, &end);  // skip the comma
    out.back().push_back({x, y});
    i = static_cast<size_t>(end - str.c_str());
  }
  return out;
}

}  // namespace

bool font_has_glyph(char c) { return c == ' ' || find_glyph(c) != nullptr; }

double text_width_mm(std::string_view text, double height_mm) {
  if (text.empty()) return 0;
  const double unit = height_mm / kCapUnits;
  return (static_cast<double>(text.size()) * kAdvanceUnits - 2.0) * unit;
}

std::vector<std::vector<Vec2>> text_strokes(std::string_view text, double height_mm) {
  std::vector<std::vector<Vec2>> out;
  const double unit = height_mm / kCapUnits;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == ' ') continue;
    const Glyph* g = find_glyph(text[i]);
    if (!g) g = find_glyph('?');
    const double x0 = static_cast<double>(i) * kAdvanceUnits;
    for (auto& line : parse(g->strokes)) {
      for (Vec2& p : line) p = Vec2{(p.x + x0) * unit, p.y * unit};
      out.push_back(std::move(line));
    }
  }
  return out;
}

}  // namespace tp::geometry
