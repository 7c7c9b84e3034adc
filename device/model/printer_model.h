// device/model/printer_model.h: what a printer is: heads, inks, resolution, buffer and speeds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tp::device {

/// One ink channel of the printer ("cyan"), in the order channels travel in a swath.
struct InkChannel {
  std::string name;
  double head_offset_x_mm = 0;   ///< offset of this ink's nozzle row from the carriage origin
  /// Optical density of this ink relative to its nominal colour (simulator colour model; 1 = nominal).
  double strength = 1;
};

/// Where the carriage's nozzle column 0 lies, seen from the printed face with the marker's
/// leading edge at the top (docs/roll-frame.md): over the left selvedge (roll x = 0, columns
/// run with roll x) or over the right one (columns run against roll x).
enum class CarriageOrigin { kLeft, kRight };

/// "left" / "right".
const char* to_string(CarriageOrigin origin);

/// Linear drop volumes up to kDefaultLargestDrop_pl, one per drop level 1 .. 2^bits - 1.
inline constexpr double kDefaultLargestDrop_pl = 12;
std::vector<double> default_drop_volumes_pl(int bits_per_pixel);

/// A printer model, as the host plans swaths for it and the simulator emulates it.
struct PrinterModel {
  std::string name = "tp-sim-1600";
  std::uint16_t usb_vendor_id = 0x1d6b;     ///< overridden per real device
  std::uint16_t usb_product_id = 0x0104;
  std::string ieee1284_id = "MFG:TextilePrint;MDL:TP-SIM-1600;CMD:TPWP;CLS:PRINTER;";

  std::vector<InkChannel> inks{{"cyan"}, {"magenta"}, {"yellow"}, {"black"}};
  int dpi_x = 600;                 ///< native resolution across the fabric
  int dpi_y = 600;                 ///< native resolution along the feed
  int nozzles_per_ink = 1280;      ///< nozzles in one ink's row
  int nozzle_pitch_rows = 1;       ///< nozzle spacing in print rows at dpi_y
  int bits_per_pixel = 2;          ///< drop levels: 2 bits = none/small/medium/large
  double print_width_mm = 1650;    ///< widest printable fabric
  std::uint32_t swath_buffer_bytes = 64u << 20;  ///< printer memory for swaths awaiting printing
  std::uint16_t swath_buffer_slots = 8;          ///< swaths the printer can hold at once
  double carriage_speed_mm_s = 1500;
  double feed_speed_mm_s = 200;
  std::uint16_t protocol_version = 1;
  CarriageOrigin carriage_origin = CarriageOrigin::kLeft;
  /// Volume of one drop at each level 1 .. 2^bits_per_pixel - 1, picolitres (ink use in the report).
  std::vector<double> drop_volume_pl{4, 8, 12};

  // Colour on the fabric (the simulator's colorimetric printer, docs/colour.md).
  /// Fabric preset the printer is loaded with: "cotton", "polyester-satin" or "silk".
  std::string fabric = "cotton";
  /// Yule-Nielsen n of the mixing model; 0 = the fabric preset's own.
  double yule_nielsen_n = 0;
  /// Share of a pixel one drop of each level covers once it has spread, 0..1 per level 1 ..
  /// 2^bits_per_pixel - 1; empty = from the drop volumes (area grows as volume^(2/3)) and the
  /// fabric's spread.
  std::vector<double> drop_coverage;
};

/// The fabric presets the colour model knows, in the order documented.
inline constexpr const char* kFabricPresets[] = {"cotton", "polyester-satin", "silk"};

}  // namespace tp::device
