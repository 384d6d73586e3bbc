#pragma once
// The settings `impact_velocity` and `impact_open_time` (lib/engines/impact_criteria.hpp) as
// fields of any time-stepping engine's settings schema, so every engine reads them alike.
#include <limits>
#include <string>
#include <vector>

#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/settings/setting_fields.hpp"

namespace impactbench::engines {

/// `fields` followed by the two criteria's fields, read into `O::*criteria`.
template <typename O>
std::vector<SettingField<O>> with_impact_criteria(std::vector<SettingField<O>> fields,
                                                  ImpactCriteria O::*criteria) {
  const NumberRange at_least_zero{0.0, std::numeric_limits<double>::infinity()};
  for (double ImpactCriteria::*value :
       {&ImpactCriteria::impact_velocity, &ImpactCriteria::impact_open_time}) {
    const std::string key =
        value == &ImpactCriteria::impact_velocity ? "impact_velocity" : "impact_open_time";
    fields.push_back(
        {key, "a number " + at_least_zero.text(),
         [criteria, value, at_least_zero](O& o, const std::string& v) {
           o.*criteria.*value = parse_number(v, at_least_zero);
         },
         [criteria, value](const O& o) { return output::number_text(o.*criteria.*value); }});
  }
  return fields;
}

}  // namespace impactbench::engines
