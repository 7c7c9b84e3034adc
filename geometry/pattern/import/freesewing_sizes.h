// geometry/pattern/import/freesewing_sizes.h: FreeSewing's standard measurement sets (cisFemaleAdult28..46) as
// dress-form measurements.
#pragma once

#include <optional>
#include <string_view>

#include "geometry/body/measurements.h"

namespace tp::geometry {

/// The size a FreeSewing export is named for ("teagan-cisFemaleAdult34.svg" -> 34), if any.
std::optional<int> freesewing_size_in_name(std::string_view file_name);

/// The dress-form measurements of FreeSewing's `cisFemaleAdult<size>` set (@freesewing/models:
/// the set is its neck girth in cm; every other measurement is the base set's, neck 340 mm,
/// scaled by the neck ratio with a per-kind damping: 1 for girths, 0.85 waist, 0.65 vertical
/// lengths, 0.6 seat, 0.5 arcs). Hips are FreeSewing's seat (the fullest girth). The nape-to-waist
/// length is the one at which the dress form measures FreeSewing's hpsToWaistBack from the high
/// point of the shoulder down its back (dress_form_hps_to_waist_back_mm; 70 mm shorter at 42);
/// the height is waist-to-floor plus that length over the dress form's nape ratio. nullopt when
/// `size` is not one of 28, 30, ..., 46.
std::optional<BodyMeasurements> freesewing_cis_female_adult(int size);

}  // namespace tp::geometry
