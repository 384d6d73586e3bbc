#include "tools/engines/ode/ode_settings.hpp"

#include <limits>

#include "lib/engines/impact_criteria_fields.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines {

const SettingsSchema<OdeSettings>& ode_settings_schema() {
  using O = OdeSettings;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const SettingsSchema<O> schema(
      engine_name::kOde, "ODE",
      with_impact_criteria<O>(
          {number_field("dt", &O::dt, {0.0, kInf, true}),
           choice_field<O, OdeStepper>(
               "stepper", &O::stepper,
               {{"exact", OdeStepper::kExact}, {"quick", OdeStepper::kQuick}}),
           whole_field("quick_iterations", &O::quick_iterations, 1, 10000),
           choice_field<O, OdeFriction>(
               "friction", &O::friction,
               {{"pyramid", OdeFriction::kPyramid}, {"box", OdeFriction::kBox}}),
           number_field("erp", &O::erp, {0.0, 1.0}), number_field("cfm", &O::cfm, {0.0, 1.0}),
           number_field("bounce_velocity", &O::bounce_velocity, {0.0, 1000.0}),
           whole_field("max_contacts", &O::max_contacts, 1, 64)},
          &O::impact));
  return schema;
}

const EngineSettings& ode_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = ode_settings_schema().describe();
    s.dt_keys = {"dt"};
    s.solver_key = [](const std::string&) { return std::string("stepper"); };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
