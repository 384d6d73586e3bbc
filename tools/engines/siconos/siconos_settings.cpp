#include "tools/engines/siconos/siconos_settings.hpp"

#include <limits>

#include "lib/engines/impact_criteria_fields.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines {

const SettingsSchema<SiconosSettings>& siconos_settings_schema() {
  using S = SiconosSettings;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const SettingsSchema<S> schema(
      engine_name::kSiconos, "Siconos",
      with_impact_criteria<S>(
          {choice_field<S, SiconosScheme>("scheme", &S::scheme,
                                          {{"moreau_jean", SiconosScheme::kMoreauJean},
                                           {"event_driven", SiconosScheme::kEventDriven}}),
           number_field("dt", &S::dt, {0.0, kInf, true}),
           number_field("theta", &S::theta, {0.5, 1.0}),
           number_field("gamma", &S::gamma, {0.0, 1.0}),
           number_field("activation_threshold", &S::activation_threshold, {0.0, 1.0}),
           choice_field<S, SiconosSolver>("solver", &S::solver,
                                          {{"nsgs", SiconosSolver::kNsgs},
                                           {"lemke", SiconosSolver::kLemke},
                                           {"enum", SiconosSolver::kEnum},
                                           {"cpg", SiconosSolver::kCpg}}),
           number_field("tolerance", &S::tolerance, {0.0, 1.0, true}),
           whole_field("max_iterations", &S::max_iterations, 1, 1000000),
           number_field("rtol", &S::rtol, {0.0, 1.0, true}),
           number_field("atol", &S::atol, {0.0, 1.0, true}),
           number_field("event_tolerance", &S::event_tolerance, {0.0, 1.0, true})},
          &S::impact));
  return schema;
}

const EngineSettings& siconos_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = siconos_settings_schema().describe();
    s.dt_keys = {"dt"};
    s.tolerance_keys = {"tolerance"};
    s.solver_key = [](const std::string&) { return std::string("solver"); };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
