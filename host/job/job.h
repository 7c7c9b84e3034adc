// host/job/job.h: a garment job as the host understands it, after its manifest is validated.
//
// Lengths are millimetres (the manifest may say "1 cm" or "0.5 in"; intake converts). Asset
// paths are absolute paths inside the job package, already checked to stay inside it.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "host/job/calibration_set.h"
#include "host/job/printer_choice.h"

namespace tp::host {

/// Limits of the fit checks on a sewn garment (docs/garments.md, "Fit checks"); a garment
/// beyond any of them fails the garment stage.
struct GarmentChecksSpec {
  double max_stitch_gap_mm = 2;              ///< largest distance between a stitch's two sides before merging
  double max_self_intersections = 0.002;     ///< intersecting triangle pairs, fraction of triangles
  double max_inside_body = 0.002;            ///< vertices inside the body, fraction of vertices
  double max_body_crossings = 1;             ///< triangles crossing the body's surface, fraction (1: not limited)
  double max_off_body = 0.05;                ///< area farther than 150 mm from the body, fraction
};

/// Where the garment comes from.
/// The fabric the garment is draped in: a preset ("jersey", "cotton-poplin", "silk-satin",
/// "denim") with any of its values overridden.
struct GarmentMaterialSpec {
  std::string preset = "cotton-poplin";
  std::optional<double> density_g_m2;
  std::optional<double> stretch_limit;
  std::optional<double> bending_rigidity_uN_m;
  std::optional<double> friction;
};

struct GarmentSpec {
  std::optional<std::filesystem::path> pattern;       ///< pattern file (native JSON, GarmentCode, SVG, DXF)
  std::string pattern_format = "auto";
  std::optional<std::filesystem::path> garment_mesh;  ///< OBJ garment whose UVs are the pieces, in mm
  std::string sample;                                 ///< project sample garment ("skirt8"), if no file
  std::string size = "M";
  /// Body: a dress form from measurements, or a mesh file with its units, or none (flat job).
  std::string body_kind = "none";                     ///< "none", "dress_form", "mesh"
  std::vector<std::pair<std::string, double>> dress_form_mm;  ///< measurement name -> mm
  std::optional<std::filesystem::path> body_mesh;
  double body_mesh_scale_to_mm = 1.0;
  std::string stitches = "pattern";                   ///< "pattern", "suggest"
  double suggest_min_score = 0.7;                     ///< "suggest": suggestions scoring below are dropped
  std::optional<std::filesystem::path> stitches_file; ///< stitches file (printctl pattern suggest), added to the pattern's
  GarmentChecksSpec checks;
  double mesh_edge_mm = 15;                           ///< target triangle edge length
  GarmentMaterialSpec material;                       ///< fabric of the drape
  bool drape = true;                                  ///< settle the sewn garment under gravity (previews)
  std::string sewing = "auto";                        ///< sewing solver: "auto", "arap" or "xpbd" (self-collision)
  std::string correspondence = "sewn";                ///< "sewn" or "draped": the garment the design is made on
};

/// One layer of the print design (units mm, directions unit-free).
struct DesignLayerSpec {
  std::string type;                                   ///< "planar", "cylindrical", "stroke", "texture"
  std::string name;
  double opacity = 1.0;
  std::optional<std::filesystem::path> image;         ///< image file
  std::string procedural;                             ///< or a procedural texture: "marbling", "stripes", ...
  int procedural_seed = 1;
  int procedural_size_px = 1024;
  int procedural_count = 12;                          ///< stripes: stripe pairs per tile
  bool procedural_vertical = true;                    ///< stripes: run along the tile height
  std::array<double, 3> centre_mm{0, 0, 0};
  std::array<double, 3> normal{0, 0, 1};
  std::array<double, 3> up{0, 1, 0};
  double width_mm = 0;
  double height_mm = 0;
  bool repeat = false;
  std::optional<std::array<double, 3>> axis_origin_mm;
  std::optional<std::array<double, 3>> axis_direction;
  double tile_width_mm = 0;
  double tile_height_mm = 0;
  double rotation_deg = 0;
  std::array<double, 2> offset_mm{0, 0};
  std::vector<std::array<double, 3>> points_mm;       ///< stroke polyline
  double radius_mm = 5;
  std::array<int, 4> colour_rgba{0, 0, 0, 255};
  double hardness = 0.8;
  std::optional<std::filesystem::path> mesh;          ///< texture transfer: textured OBJ
  double mesh_scale_to_mm = 1.0;                      ///< texture transfer: the OBJ's units
  double max_distance_mm = 30;                        ///< texture transfer: farther garment points stay unprinted
  // Text layers (placed like a planar layer: centre, normal, up; colour_rgba is the fill).
  std::string text;                           ///< "{name} {number}": fields of the order's copy
  std::optional<std::filesystem::path> font;  ///< font file; DejaVu Sans Bold if absent
  double text_size_mm = 40;                   ///< height of a capital letter
  double outline_mm = 0;
  std::array<int, 4> outline_rgba{255, 255, 255, 255};
};

/// One size of an order (docs/orders.md).
struct OrderSizeSpec {
  std::string size;  ///< size-chart name or measurement text ("L:hips=1120")
  int quantity = 1;
  std::optional<std::filesystem::path> pattern;               ///< imported patterns: this size's pattern file
  std::vector<std::pair<std::string, double>> dress_form_mm;  ///< imported patterns: this size's body
};

/// A production order: the job's garment in several sizes and copies, its design made on the
/// base size and re-projected onto the others.
struct OrderSpec {
  std::string base_size;           ///< the size the design's 3D coordinates are on
  std::string placement = "body";  ///< "body" (kept on the body, in mm) or "graded"
  /// "order": job.marker's budget for the order's one marker; "per_garment": that times the garments.
  std::string marker_budget = "order";
  std::vector<OrderSizeSpec> sizes;
  /// Per copy (sizes in order, each `quantity` times): field name -> text, for text layers.
  std::vector<std::vector<std::pair<std::string, std::string>>> copies;
  std::optional<std::filesystem::path> copies_csv;  ///< where `copies` came from, if a CSV asset
  int garments() const {
    int n = 0;
    for (const auto& s : sizes) n += s.quantity;
    return n;
  }
};

/// Per-edge allowance override.
struct EdgeAllowance {
  std::string piece;
  std::string edge;
  double allowance_mm = 0;
};

struct FinishingSpec {
  double seam_allowance_mm = 10;
  double hem_allowance_mm = 20;
  std::vector<EdgeAllowance> edges;
  std::string corner_style = "mitre";                 ///< "mitre", "square", "mirror"
  bool notches = true;
  std::string labels = "inside";                      ///< label and grain arrow: "inside", "separate", "none"
  std::string cutter_roll_axis = "x";                 ///< cut-file axis along the roll: "x" or "y"
};

struct DefectZone {
  double x_mm = 0, y_mm = 0, width_mm = 0, length_mm = 0;
};

struct MarkerSpec {
  double fabric_width_mm = 1500;
  double gap_mm = 4;
  double edge_margin_mm = 10;
  std::string rotations = "grain";                    ///< "grain" (0/180), "90", "free", "fixed"
  bool mirror = false;
  double time_limit_s = 5;
  /// Reproducible budget: separator iterations instead of seconds (0: the time limit applies).
  /// The manifest's default (20,000) unless the job gives seconds or `reproducible: false`; the marker then depends on
  /// the pieces, the marker fields and the seed alone, whatever the machine's load.
  int iterations = 0;
  int seed = 1;
  std::optional<double> max_length_mm;
  std::vector<DefectZone> defects;
};

struct PrintSpec {
  PrinterChoice printer = PrinterChoice::kSim;        ///< kSim (printsim) or kUsb; never kNone
  std::optional<std::filesystem::path> printer_model; ///< printer description file; built-in if absent
  int dpi = 600;
  int passes = 1;
  bool bidirectional = false;
  std::string screen = "blue-noise";                  ///< "blue-noise", "error-diffusion"
  int levels = 4;                                     ///< drop levels incl. none: 2 or 4
  std::optional<std::filesystem::path> icc_profile;
  std::optional<std::filesystem::path> calibration;          ///< a calibration set's calibration.json
  std::optional<std::filesystem::path> calibration_profile;  ///< its profile (docs/colour.md)
  std::optional<CalibrationSet> calibration_set;             ///< the set read: curves, ink limit
  /// Calibration charts only: the design's R, G, B drive these inks directly (docs/colour.md).
  std::vector<std::string> device_inks;
  double ink_limit_pct = 280;
  bool separations_tiff = false;
  int preview_dpi = 50;
  std::string transfer = "direct";                    ///< "direct" or "sublimation" (printed mirrored)
};

/// A validated job.
struct Job {
  std::string name;
  std::filesystem::path package_root;                 ///< folder holding job.json and its assets
  std::filesystem::path manifest;                     ///< .../job.json
  GarmentSpec garment;
  std::vector<DesignLayerSpec> design;
  FinishingSpec finishing;
  MarkerSpec marker;
  PrintSpec print;
  std::optional<OrderSpec> order;  ///< absent: one garment in garment.size
};

}  // namespace tp::host
