// device/model/printer_model_file.cpp: parser, writer and validation of printer model files.
#include "device/model/printer_model_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

namespace tp::device {

namespace {

constexpr std::string_view kHeader = "tp-printer-model 1";
constexpr std::size_t kMaxModelFileBytes = 64 * 1024;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Parses an integer (decimal or 0x hex) within [lo, hi].
bool parse_int(std::string_view v, long long lo, long long hi, long long& out) {
  int base = 10;
  if (v.size() > 2 && v[0] == '0' && (v[1] == 'x' || v[1] == 'X')) {
    v.remove_prefix(2);
    base = 16;
  }
  if (v.empty()) return false;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), out, base);
  return ec == std::errc() && p == v.data() + v.size() && out >= lo && out <= hi;
}

bool parse_double(std::string_view v, double lo, double hi, double& out) {
  if (v.empty()) return false;
  auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  return ec == std::errc() && p == v.data() + v.size() && std::isfinite(out) && out >= lo && out <= hi;
}

bool valid_ink_name(std::string_view n) {
  if (n.empty() || n.size() > 32) return false;
  for (char c : n)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return false;
  return true;
}

bool printable(std::string_view s) {
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7F) return false;
  return true;
}

std::string fmt_double(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // Shortest form that still reads back exactly.
  for (int prec = 1; prec <= 17; ++prec) {
    char s[64];
    std::snprintf(s, sizeof s, "%.*g", prec, v);
    double back = 0;
    if (std::sscanf(s, "%lf", &back) == 1 && back == v) return s;
  }
  return buf;
}

}  // namespace

const char* to_string(CarriageOrigin origin) {
  switch (origin) {
    case CarriageOrigin::kLeft: return "left";
    case CarriageOrigin::kRight: return "right";
  }
  return "left";
}

std::vector<double> default_drop_volumes_pl(int bits_per_pixel) {
  const int levels = (1 << std::clamp(bits_per_pixel, 1, 8)) - 1;
  std::vector<double> v;
  for (int k = 1; k <= levels; ++k) v.push_back(kDefaultLargestDrop_pl * k / levels);
  return v;
}

Status validate_printer_model(const PrinterModel& m) {
  auto bad = [&](const std::string& field, const std::string& why) {
    return fail(ErrorCode::kInvalidArgument, "printer model '" + m.name + "': " + field + ": " + why);
  };
  if (m.name.empty() || m.name.size() > 64 || !printable(m.name)) return bad("name", "1..64 printable characters");
  if (m.ieee1284_id.size() > 1000 || !printable(m.ieee1284_id)) return bad("ieee1284_id", "at most 1000 printable characters");
  if (m.inks.empty() || m.inks.size() > 16) return bad("ink", "1..16 inks required");
  std::set<std::string> names;
  for (const auto& ink : m.inks) {
    if (!valid_ink_name(ink.name)) return bad("ink", "name '" + ink.name + "' must be 1..32 of [a-z0-9_-]");
    if (!names.insert(ink.name).second) return bad("ink", "'" + ink.name + "' listed twice");
    if (!(std::abs(ink.head_offset_x_mm) <= 1000)) return bad("ink", "'" + ink.name + "' head offset beyond 1000 mm");
  }
  if (m.dpi_x < 50 || m.dpi_x > 4800) return bad("dpi_x", "must be 50..4800");
  if (m.dpi_y < 50 || m.dpi_y > 4800) return bad("dpi_y", "must be 50..4800");
  if (m.nozzles_per_ink < 1 || m.nozzles_per_ink > 65535) return bad("nozzles_per_ink", "must be 1..65535");
  if (m.nozzle_pitch_rows < 1 || m.nozzle_pitch_rows > 64) return bad("nozzle_pitch_rows", "must be 1..64");
  if (m.bits_per_pixel != 1 && m.bits_per_pixel != 2 && m.bits_per_pixel != 4 && m.bits_per_pixel != 8)
    return bad("bits_per_pixel", "must be 1, 2, 4 or 8");
  if (!(m.print_width_mm >= 10 && m.print_width_mm <= 5000)) return bad("print_width_mm", "must be 10..5000");
  if (m.swath_buffer_bytes < (64u << 10)) return bad("swath_buffer_bytes", "must be at least 65536");
  if (m.swath_buffer_slots < 1 || m.swath_buffer_slots > 1024) return bad("swath_buffer_slots", "must be 1..1024");
  if (!(m.carriage_speed_mm_s > 0 && m.carriage_speed_mm_s <= 20000)) return bad("carriage_speed_mm_s", "must be in (0, 20000]");
  if (!(m.feed_speed_mm_s > 0 && m.feed_speed_mm_s <= 20000)) return bad("feed_speed_mm_s", "must be in (0, 20000]");
  if (m.protocol_version < 1) return bad("protocol_version", "must be at least 1");
  if (m.drop_volume_pl.size() != (std::size_t{1} << m.bits_per_pixel) - 1)
    return bad("drop_volume_pl", "needs one volume per drop level (" + std::to_string((1 << m.bits_per_pixel) - 1) +
                                     " for " + std::to_string(m.bits_per_pixel) + " bits per pixel), got " +
                                     std::to_string(m.drop_volume_pl.size()));
  for (double v : m.drop_volume_pl)
    if (!(v > 0 && v <= 1000)) return bad("drop_volume_pl", "volumes must be in (0, 1000] pL");
  if (std::find(std::begin(kFabricPresets), std::end(kFabricPresets), m.fabric) == std::end(kFabricPresets))
    return bad("fabric", "'" + m.fabric + "' is not a preset (cotton, polyester-satin, silk)");
  if (!(m.yule_nielsen_n == 0 || (m.yule_nielsen_n >= 1 && m.yule_nielsen_n <= 10)))
    return bad("yule_nielsen_n", "must be 0 (the fabric's) or 1..10");
  if (!m.drop_coverage.empty() && m.drop_coverage.size() != m.drop_volume_pl.size())
    return bad("drop_coverage", "needs one coverage per drop level (" + std::to_string(m.drop_volume_pl.size()) +
                                    "), got " + std::to_string(m.drop_coverage.size()));
  for (double c : m.drop_coverage)
    if (!(c > 0 && c <= 1)) return bad("drop_coverage", "coverages must be in (0, 1]");
  for (const auto& ink : m.inks)
    if (!(ink.strength >= 0.05 && ink.strength <= 5)) return bad("ink_strength", "'" + ink.name + "' must be 0.05..5");
  return {};
}

Result<PrinterModel> parse_printer_model(std::string_view text, std::string_view source) {
  const std::string src(source);
  if (text.size() > kMaxModelFileBytes)
    return fail(ErrorCode::kParse, src + ": larger than " + std::to_string(kMaxModelFileBytes) + " bytes");
  PrinterModel m;
  m.inks.clear();
  bool header_seen = false;
  std::set<std::string> seen;
  std::map<std::string, double> strengths;
  std::size_t line_no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = trim(text.substr(0, nl));
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    const std::string where = src + ":" + std::to_string(line_no);
    if (line.empty() || line.front() == '#') continue;
    if (!header_seen) {
      if (line != kHeader)
        return fail(ErrorCode::kParse, where + ": expected the header line '" + std::string(kHeader) + "'");
      header_seen = true;
      continue;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) return fail(ErrorCode::kParse, where + ": expected 'key = value'");
    const std::string key(trim(line.substr(0, eq)));
    const std::string_view val = trim(line.substr(eq + 1));
    if (key != "ink" && !seen.insert(key).second)
      return fail(ErrorCode::kParse, where + ": key '" + key + "' given twice");
    auto bad = [&](const std::string& expect) {
      return fail(ErrorCode::kParse, where + ": key '" + key + "': expected " + expect + ", got '" + std::string(val) + "'");
    };
    long long i = 0;
    double d = 0;
    if (key == "name") {
      if (val.empty() || val.size() > 64 || !printable(val)) return bad("1..64 printable characters");
      m.name = std::string(val);
    } else if (key == "ieee1284_id") {
      if (val.size() > 1000 || !printable(val)) return bad("at most 1000 printable characters");
      m.ieee1284_id = std::string(val);
    } else if (key == "usb_vendor_id" || key == "usb_product_id") {
      if (!parse_int(val, 0, 0xFFFF, i)) return bad("an integer in 0..0xffff");
      (key == "usb_vendor_id" ? m.usb_vendor_id : m.usb_product_id) = static_cast<std::uint16_t>(i);
    } else if (key == "dpi_x" || key == "dpi_y") {
      if (!parse_int(val, 50, 4800, i)) return bad("an integer in 50..4800");
      (key == "dpi_x" ? m.dpi_x : m.dpi_y) = static_cast<int>(i);
    } else if (key == "nozzles_per_ink") {
      if (!parse_int(val, 1, 65535, i)) return bad("an integer in 1..65535");
      m.nozzles_per_ink = static_cast<int>(i);
    } else if (key == "nozzle_pitch_rows") {
      if (!parse_int(val, 1, 64, i)) return bad("an integer in 1..64");
      m.nozzle_pitch_rows = static_cast<int>(i);
    } else if (key == "bits_per_pixel") {
      if (!parse_int(val, 1, 8, i) || (i != 1 && i != 2 && i != 4 && i != 8)) return bad("1, 2, 4 or 8");
      m.bits_per_pixel = static_cast<int>(i);
    } else if (key == "print_width_mm") {
      if (!parse_double(val, 10, 5000, d)) return bad("a number in 10..5000");
      m.print_width_mm = d;
    } else if (key == "swath_buffer_bytes") {
      if (!parse_int(val, 65536, 0xFFFFFFFFLL, i)) return bad("an integer in 65536..4294967295");
      m.swath_buffer_bytes = static_cast<std::uint32_t>(i);
    } else if (key == "swath_buffer_slots") {
      if (!parse_int(val, 1, 1024, i)) return bad("an integer in 1..1024");
      m.swath_buffer_slots = static_cast<std::uint16_t>(i);
    } else if (key == "carriage_speed_mm_s" || key == "feed_speed_mm_s") {
      if (!parse_double(val, 1e-3, 20000, d)) return bad("a number in (0, 20000]");
      (key == "carriage_speed_mm_s" ? m.carriage_speed_mm_s : m.feed_speed_mm_s) = d;
    } else if (key == "carriage_origin") {
      if (val == "left") m.carriage_origin = CarriageOrigin::kLeft;
      else if (val == "right") m.carriage_origin = CarriageOrigin::kRight;
      else return bad("'left' or 'right'");
    } else if (key == "drop_volume_pl") {
      // "drop_volume_pl = 4 8 12": picolitres per drop level, smallest first.
      m.drop_volume_pl.clear();
      for (std::string_view rest = val; !rest.empty();) {
        const std::size_t sp = rest.find_first_of(" \t");
        if (!parse_double(rest.substr(0, sp), 1e-6, 1000, d) || m.drop_volume_pl.size() >= 255)
          return bad("1..255 volumes in (0, 1000] pL separated by spaces");
        m.drop_volume_pl.push_back(d);
        rest = sp == std::string_view::npos ? std::string_view{} : trim(rest.substr(sp));
      }
      if (m.drop_volume_pl.empty()) return bad("1..255 volumes in (0, 1000] pL separated by spaces");
    } else if (key == "drop_coverage") {
      // "drop_coverage = 0.5 0.8 1": share of a pixel each drop level covers once spread.
      for (std::string_view rest = val; !rest.empty();) {
        const std::size_t sp = rest.find_first_of(" \t");
        if (!parse_double(rest.substr(0, sp), 1e-6, 1, d) || m.drop_coverage.size() >= 255)
          return bad("1..255 coverages in (0, 1] separated by spaces");
        m.drop_coverage.push_back(d);
        rest = sp == std::string_view::npos ? std::string_view{} : trim(rest.substr(sp));
      }
      if (m.drop_coverage.empty()) return bad("1..255 coverages in (0, 1] separated by spaces");
    } else if (key == "fabric") {
      if (std::find(std::begin(kFabricPresets), std::end(kFabricPresets), val) == std::end(kFabricPresets))
        return bad("a fabric preset: cotton, polyester-satin or silk");
      m.fabric = std::string(val);
    } else if (key == "yule_nielsen_n") {
      if (!parse_double(val, 0, 10, d) || (d != 0 && d < 1)) return bad("0 (the fabric's) or a number in 1..10");
      m.yule_nielsen_n = d;
    } else if (key == "ink_strength") {
      // "ink_strength = <ink> <factor>": applied once every ink line is read.
      const std::size_t sp = val.find_first_of(" \t");
      if (sp == std::string_view::npos || !parse_double(trim(val.substr(sp)), 0.05, 5, d))
        return bad("'<ink name> <factor in 0.05..5>'");
      if (!strengths.emplace(std::string(val.substr(0, sp)), d).second) return bad("each ink's strength once");
    } else if (key == "protocol_version") {
      if (!parse_int(val, 1, 65535, i)) return bad("an integer in 1..65535");
      m.protocol_version = static_cast<std::uint16_t>(i);
    } else if (key == "ink") {
      // "ink = <name> [head offset mm]", in swath channel order.
      const std::size_t sp = val.find_first_of(" \t");
      InkChannel ink;
      ink.name = std::string(val.substr(0, sp));
      if (!valid_ink_name(ink.name)) return bad("'<name> [offset_mm]' with a name of 1..32 of [a-z0-9_-]");
      if (sp != std::string_view::npos && !parse_double(trim(val.substr(sp)), -1000, 1000, d))
        return bad("a head offset in -1000..1000 mm after the ink name");
      ink.head_offset_x_mm = sp == std::string_view::npos ? 0 : d;
      if (m.inks.size() >= 16) return bad("at most 16 inks");
      m.inks.push_back(std::move(ink));
    } else {
      return fail(ErrorCode::kParse, where + ": unknown key '" + key + "'");
    }
  }
  if (!header_seen) return fail(ErrorCode::kParse, src + ": empty; expected the header line '" + std::string(kHeader) + "'");
  for (const char* required : {"name", "dpi_x", "dpi_y"})
    if (!seen.count(required)) return fail(ErrorCode::kParse, src + ": required key '" + required + "' missing");
  if (m.inks.empty()) return fail(ErrorCode::kParse, src + ": no 'ink' lines; a printer needs at least one ink");
  if (!seen.count("drop_volume_pl")) m.drop_volume_pl = default_drop_volumes_pl(m.bits_per_pixel);
  for (const auto& strength : strengths) {
    // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const std::string& name = strength.first;
    auto it = std::find_if(m.inks.begin(), m.inks.end(), [&](const InkChannel& c) { return c.name == name; });
    if (it == m.inks.end()) return fail(ErrorCode::kParse, src + ": key 'ink_strength': no ink '" + name + "'");
    it->strength = strength.second;
  }
  if (auto s = validate_printer_model(m); !s) return fail(ErrorCode::kParse, src + ": " + s.error().message);
  return m;
}

Result<PrinterModel> load_printer_model(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kInvalidArgument, path.string() + ": cannot open printer model file");
  std::string text;
  text.resize(kMaxModelFileBytes + 1);
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return parse_printer_model(text, path.string());
}

std::string format_printer_model(const PrinterModel& m) {
  std::ostringstream o;
  char hex[16];
  o << kHeader << "\n";
  o << "name = " << m.name << "\n";
  std::snprintf(hex, sizeof hex, "0x%04x", m.usb_vendor_id);
  o << "usb_vendor_id = " << hex << "\n";
  std::snprintf(hex, sizeof hex, "0x%04x", m.usb_product_id);
  o << "usb_product_id = " << hex << "\n";
  o << "ieee1284_id = " << m.ieee1284_id << "\n";
  o << "dpi_x = " << m.dpi_x << "\n";
  o << "dpi_y = " << m.dpi_y << "\n";
  o << "nozzles_per_ink = " << m.nozzles_per_ink << "\n";
  o << "nozzle_pitch_rows = " << m.nozzle_pitch_rows << "\n";
  o << "bits_per_pixel = " << m.bits_per_pixel << "\n";
  o << "print_width_mm = " << fmt_double(m.print_width_mm) << "\n";
  o << "swath_buffer_bytes = " << m.swath_buffer_bytes << "\n";
  o << "swath_buffer_slots = " << m.swath_buffer_slots << "\n";
  o << "carriage_speed_mm_s = " << fmt_double(m.carriage_speed_mm_s) << "\n";
  o << "feed_speed_mm_s = " << fmt_double(m.feed_speed_mm_s) << "\n";
  o << "protocol_version = " << m.protocol_version << "\n";
  o << "carriage_origin = " << to_string(m.carriage_origin) << "\n";
  o << "drop_volume_pl =";
  for (double v : m.drop_volume_pl) o << " " << fmt_double(v);
  o << "\n";
  for (const auto& ink : m.inks) o << "ink = " << ink.name << " " << fmt_double(ink.head_offset_x_mm) << "\n";
  o << "fabric = " << m.fabric << "\n";
  if (m.yule_nielsen_n != 0) o << "yule_nielsen_n = " << fmt_double(m.yule_nielsen_n) << "\n";
  if (!m.drop_coverage.empty()) {
    o << "drop_coverage =";
    for (double c : m.drop_coverage) o << " " << fmt_double(c);
    o << "\n";
  }
  for (const auto& ink : m.inks)
    if (ink.strength != 1) o << "ink_strength = " << ink.name << " " << fmt_double(ink.strength) << "\n";
  return o.str();
}

}  // namespace tp::device
