// geometry/common/aama_layers.h: the ASTM D6673 (DXF-AAMA) layer numbers, shared by the pattern
// importer (geometry/pattern/) and the cut-file writer (geometry/cutfile/).
#pragma once

namespace tp::geometry {

/// The DXF-AAMA layers the project reads or writes; the value is the layer's number.
enum class AamaLayer : int {
  kBoundary = 1,         ///< cut line
  kTurnPoints = 2,       ///< POINTs marking corners of the boundary
  kCurvePoints = 3,      ///< POINTs marking curve points of the boundary
  kNotches = 4,          ///< notches (POINTs or short lines)
  kGradeReference = 5,   ///< grade reference line
  kMirrorLine = 6,       ///< fold line of a half piece
  kGrainLine = 7,        ///< grain line
  kInternalLines = 8,    ///< internal marking lines
  kStripeReference = 9,  ///< stripe reference line
  kPlaidReference = 10,  ///< plaid reference line
  kInternalCutouts = 11, ///< holes cut inside the piece
  kDrillHoles = 13,      ///< drill holes, as POINTs
  kSewLines = 14,        ///< sew line (the seam line inside the boundary)
  kAnnotation = 15,      ///< piece annotation text
};

/// The layer's number.
constexpr int aama_number(AamaLayer layer) { return static_cast<int>(layer); }

/// The layer's DXF name (group code 8), its number as text.
constexpr const char* aama_layer_name(AamaLayer layer) {
  switch (layer) {
    case AamaLayer::kBoundary: return "1";
    case AamaLayer::kTurnPoints: return "2";
    case AamaLayer::kCurvePoints: return "3";
    case AamaLayer::kNotches: return "4";
    case AamaLayer::kGradeReference: return "5";
    case AamaLayer::kMirrorLine: return "6";
    case AamaLayer::kGrainLine: return "7";
    case AamaLayer::kInternalLines: return "8";
    case AamaLayer::kStripeReference: return "9";
    case AamaLayer::kPlaidReference: return "10";
    case AamaLayer::kInternalCutouts: return "11";
    case AamaLayer::kDrillHoles: return "13";
    case AamaLayer::kSewLines: return "14";
    case AamaLayer::kAnnotation: return "15";
  }
  return "0";
}

}  // namespace tp::geometry
