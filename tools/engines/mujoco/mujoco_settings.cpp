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
    // The expert set (docs/reference-engines.md#expert-settings), from MuJoCo 2.2.2's
    // documentation (doc/ of the 2.2.2 tag; mujoco.readthedocs.io). Modeling, "Algorithms and
    // related settings": Newton is the best solver for most models, to be used with aggressive
    // tolerances such as 1e-10 (the scenarios' own tolerance, which --tol and the scenario set,
    // is 1e-10 on the closed-form scenarios); elliptic cones are closer to reality, and contact
    // slip is best suppressed by elliptic cones, a large impratio and Newton, the Noslip solver
    // only when that is not enough (an ad hoc step that can destabilise several interacting
    // contacts): newton, elliptic, impratio 5 (no number given; 10 threw the plank-box's box
    // 0.57 m into the plank, 1 to 5 leave it within 1.5 mm), noslip 0. Modeling, "Solver
    // parameters": larger impedances d make harder constraints (d is clamped to at most 0.9999);
    // the time constant must be at least two timesteps; the damping ratio is normally 1 (critical),
    // smaller is bouncy: solimp 0.99/0.99/1 mm (0.999 threw the plank-box's box off the plank),
    // solref time constant max(5 ms, 2 timesteps), and the damping ratio from the scenario's
    // restitution, which the scenarios need (1 would give e = 0). XML reference, option/iterations:
    // 100 by default; more for larger systems.
    s.expert = {{"solver", "newton"},
                {"cone", "elliptic"},
                {"impratio", "5"},
                {"noslip_iterations", "0"},
                {"iterations", "100"},
                {"solimp_dmin", "0.99"},
                {"solimp_dmax", "0.99"},
                {"solimp_width", "0.001"},
                {"solref_timeconst", "auto"},
                {"solref_dampratio", "restitution"}};
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines
