#include "tools/engines/moreau/moreau_settings.hpp"

#include <limits>

#include "lib/engines/impact_criteria_fields.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using O = MoreauJeanOptions;

std::vector<std::string> friction_solver_names() {
  std::vector<std::string> names;
  for (const auto& info : solvers::friction_solvers()) names.push_back(info.name);
  return names;
}

}  // namespace

const SettingsSchema<MoreauJeanOptions>& moreau_settings_schema() {
  // Ranges: beyond a million sweeps or 64 cone facets a run does not end in useful time.
  static const SettingsSchema<O> schema(
      engine_name::kMoreau, "Moreau–Jean",
      with_impact_criteria<O>(
          {number_field("dt", &O::dt, {0.0, kInf, true}),
           number_field("theta", &O::theta, {0.5, 1.0}),
           name_field("solver", &O::solver, friction_solver_names()),
           number_field("tolerance", &O::tolerance, {0.0, 1.0, true}),
           whole_field("max_iterations", &O::max_iterations, 1, 1000000),
           choice_field<O, OnFailure>("on_failure", &O::on_failure,
                                      {{"stop", OnFailure::kStop}, {"warn", OnFailure::kWarn}}),
           switch_field("cold_restart", &O::cold_restart),
           choice_field<O, ForceTreatment>(
               "forces", &O::forces,
               {{"explicit", ForceTreatment::kExplicit},
                {"linearly-implicit", ForceTreatment::kLinearlyImplicit}}),
           number_field("contact_margin", &O::contact_margin, {0.0, kInf}),
           whole_field("cone_facets", &O::cone_facets, 3, 64),
           optional_number_field("activation_horizon", &O::activation_horizon, {0.0, 1.0}, "theta"),
           number_field("activation_tolerance", &O::activation_tolerance, {0.0, kInf})},
          &O::impact),
      validate);
  return schema;
}

const EngineSettings& moreau_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = moreau_settings_schema().describe();
    s.dt_keys = {"dt"};
    s.tolerance_keys = {"tolerance"};
    s.solver_key = [](const std::string&) { return std::string("solver"); };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines::moreau_jean
