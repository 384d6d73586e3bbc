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
    // The expert set (docs/reference-engines.md#expert-settings), from ODE's manual
    // (ode.org/wiki, "Manual"). "Stepping Functions": dWorldStep solves the step's LCP exactly
    // (accurate, cost cubic in the constraint rows), dWorldQuickStep iterates and is less
    // accurate, more iterations more accurate, 20 by default: the exact step (the piles' own
    // `stepper = "quick"` still wins, as a scenario value), 50 quick iterations where quick is
    // chosen (no number for accuracy: 2.5 times ODE's default). "Joint error and the Error
    // Reduction Parameter": ERP 0.1 to 0.8 recommended, 0.2 by default: 0.2. "Soft constraint
    // and constraint force mixing": CFM 1e-10 by default in double precision, larger values
    // soften the constraint: 1e-10. "Contact" (dContactApprox1): friction limited by μ times
    // the normal force, the Coulomb pyramid, where the default box uses constant force limits:
    // pyramid. bounce_vel has no default (the caller sets it per contact): the scenarios'
    // bounces go down to mm/s, so restitution must act there: 1 mm/s.
    s.expert = {{"stepper", "exact"}, {"quick_iterations", "50"}, {"erp", "0.2"},
                {"cfm", "1e-10"},     {"friction", "pyramid"},    {"bounce_velocity", "0.001"}};
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
