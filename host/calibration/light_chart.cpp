// host/calibration/light_chart.cpp: the light corner's device-value grid.
#include "host/calibration/light_chart.h"

#include <cmath>
#include <string>

#include "host/calibration/internal/chart_print.h"

namespace tp::host {

device::CgatsTable light_chart() {
  device::CgatsTable t;
  t.type = "CTI1";
  t.keywords = {{"DESCRIPTOR", "tp light-colour profiling chart"}, {"COLOR_REP", "RGB"}};
  t.fields = {"SAMPLE_ID", "RGB_R", "RGB_G", "RGB_B"};
  const int steps = static_cast<int>(std::lround((1 - kLightChartFrom) / kLightChartStep)) + 1;
  auto value = [&](int i) { return internal::fmt(100 * (kLightChartFrom + i * kLightChartStep), 4); };
  for (int r = 0; r < steps; ++r)
    for (int g = 0; g < steps; ++g)
      for (int b = 0; b < steps; ++b)
        t.rows.push_back({std::to_string(t.rows.size() + 1), value(r), value(g), value(b)});
  return t;
}

}  // namespace tp::host
