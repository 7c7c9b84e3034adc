// geometry/nesting/placement_json.cpp: writing a strip solution as placement JSON.
#include "geometry/nesting/placement_json.h"

#include <nlohmann/json.hpp>

namespace tp::geometry {

std::string placement_json(const StripProblem& problem, const StripSolution& solution) {
  nlohmann::json j;
  j["strip_width"] = problem.width;
  j["length"] = solution.length;
  nlohmann::json list = nlohmann::json::array();
  for (const StripPlacement& p : solution.placements) {
    list.push_back({{"item", p.item_id},
                    {"rotation", p.rotation_deg},
                    {"mirror", p.mirror},
                    {"translation", {p.translation.x, p.translation.y}}});
  }
  j["placements"] = std::move(list);
  return j.dump(1) + "\n";
}

}  // namespace tp::geometry
