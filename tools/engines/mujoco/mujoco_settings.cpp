#include "tools/engines/mujoco/mujoco_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lib/engines/impact_criteria_fields.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines {

double restitution_damping_ratio(double restitution) {
  if (restitution <= 0.0) return 1.0;
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

double solref_timeconst(const MujocoSettings& settings) {
  return settings.solref_timeconst.value_or(std::max(5e-3, 2 * settings.timestep));
}

const SettingsSchema<MujocoSettings>& mujoco_settings_schema() {
  using O = MujocoSettings;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const SettingsSchema<O> schema(
      engine_name::kMujoco, "MuJoCo",
      with_impact_criteria<O>(
          {number_field("timestep", &O::timestep, {0.0, kInf, true}),
           choice_field<O, MujocoIntegrator>("integrator", &O::integrator,
                                             {{"euler", MujocoIntegrator::kEuler},
                                              {"rk4", MujocoIntegrator::kRk4},
                                              {"implicit", MujocoIntegrator::kImplicit}}),
           choice_field<O, MujocoSolver>("solver", &O::solver,
                                         {{"pgs", MujocoSolver::kPgs},
                                          {"cg", MujocoSolver::kCg},
                                          {"newton", MujocoSolver::kNewton}}),
           whole_field("iterations", &O::iterations, 1, 100000),
           number_field("tolerance", &O::tolerance, {0.0, 1.0}),
           choice_field<O, MujocoCone>(
               "cone", &O::cone,
               {{"pyramidal", MujocoCone::kPyramidal}, {"elliptic", MujocoCone::kElliptic}}),
           number_field("impratio", &O::impratio, {0.0, kInf, true}),
           whole_field("noslip_iterations", &O::noslip_iterations, 0, 100000),
           optional_number_field("solref_timeconst", &O::solref_timeconst, {0.0, kInf, true},
                                 "auto"),
           optional_number_field("solref_dampratio", &O::solref_dampratio, {0.0, kInf, true},
                                 "restitution"),
           number_field("solimp_dmin", &O::solimp_dmin, {0.0, 1.0, true, true}),
           number_field("solimp_dmax", &O::solimp_dmax, {0.0, 1.0, true, true}),
           number_field("solimp_width", &O::solimp_width, {0.0, kInf})},
          &O::impact),
      [](const O& o) {
        if (o.solimp_dmin > o.solimp_dmax)
          throw SettingError(engine_name::kMujoco, "solimp_dmin", "must not exceed solimp_dmax");
        // A contact spring faster than two steps is not resolved by the step (MuJoCo's own
        // positive form raises such a time constant to two steps): refuse it.
        if (o.solref_timeconst && *o.solref_timeconst < 2 * o.timestep * (1 - 1e-12))
          throw SettingError(engine_name::kMujoco, "solref_timeconst",
                             "must be at least two timesteps");
      });
  return schema;
}

const EngineSettings& mujoco_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = mujoco_settings_schema().describe();
    s.dt_keys = {"timestep"};
    s.tolerance_keys = {"tolerance"};
    s.solver_key = [](const std::string&) { return std::string("solver"); };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
