// Every setting of every engine, through the path `impactbench run` takes (the settings
// resolved by engines::resolve_run_options, the engine run through the registry): a
// non-default value is in force in the run's settings, marked as given on the command line,
// and changes what the setting is meant to change. The table below is checked against each
// engine's keys, so a new key without a row fails here.
#include <cmath>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

/// What a setting is expected to change, measured on the run with it against the run without.
enum class Effect {
  kTrajectory,        ///< the positions of some sample differ
  kSolverIterations,  ///< the total solver iterations (sweeps, pivots) differ
  kImpulses,          ///< the sum of normal contact impulses differs
  kContactRecords,    ///< the number of contact records over all steps differs
  kSampleCount,       ///< the number of trajectory samples differs
  kEventCount,        ///< the number of events differs
  kImpactEvents,      ///< the number of events of kind "impact" differs
  kCvodeSteps,        ///< the event engine's CVODE step count differs
  kRunFails,          ///< the run stops with an error (the baseline completes)
  kRunCompletes,      ///< the run completes (the baseline stops with an error)
  kNone,              ///< no shipped scenario shows one (the row says why)
};

struct MatrixRow {
  std::string engine;
  std::string key;
  std::string value;
  std::string scenario;
  double duration;
  Effect effect;
  /// Settings both runs share, so that the effect can show (e.g. a solver for cone_facets).
  std::vector<std::pair<std::string, std::string>> context = {};
  scenario::ParameterOverrides overrides = {};
  std::string no_effect_because = {};  ///< for Effect::kNone
};

void PrintTo(const MatrixRow& row, std::ostream* out) {
  *out << row.engine << "." << row.key << "=" << row.value << " on " << row.scenario;
}

const std::vector<MatrixRow>& matrix() {
  static const std::vector<MatrixRow> rows = {
      // Moreau–Jean
      {"moreau", "dt", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      {"moreau", "theta", "1", "plank_box", 0.3, Effect::kTrajectory},
      {"moreau",
       "solver",
       "lemke",
       "disk_pile",
       0.3,
       Effect::kSolverIterations,
       {},
       {{"count", 20}}},
      {"moreau",
       "tolerance",
       "1e-6",
       "disk_pile",
       0.3,
       Effect::kSolverIterations,
       {},
       {{"count", 20}}},
      {"moreau",
       "max_iterations",
       "3",
       "disk_pile",
       0.3,
       Effect::kSolverIterations,
       {{"on_failure", "warn"}},
       {{"count", 20}}},
      // disk_pile says on_failure = "warn" and cold_restart = false (scenarios/disk_pile.toml).
      {"moreau",
       "on_failure",
       "stop",
       "disk_pile",
       0.3,
       Effect::kRunFails,
       {{"max_iterations", "2"}},
       {{"count", 20}}},
      // Three sweeps leave most steps unconverged: each is solved a second time from zero.
      {"moreau",
       "cold_restart",
       "true",
       "disk_pile",
       0.3,
       Effect::kSolverIterations,
       {{"on_failure", "warn"}, {"max_iterations", "3"}},
       {{"count", 20}}},
      {"moreau", "forces", "explicit", "plank_box", 0.3, Effect::kTrajectory},
      // With no margin a contact is found only once it is penetrated: the impact comes late.
      {"moreau",
       "contact_margin",
       "0",
       "bouncing_ball",
       1.0,
       Effect::kNone,
       {},
       {},
       "the candidate search follows the motion (a contact predicted to close within the step is "
       "always a candidate), so the margin only adds candidates that stay inactive"},
      {"moreau",
       "cone_facets",
       "4",
       "sphere_spin",
       0.3,
       Effect::kTrajectory,
       {{"solver", "lemke"}}},
      {"moreau", "activation_horizon", "1", "bouncing_ball", 3.0, Effect::kTrajectory},
      {"moreau", "activation_tolerance", "0.005", "bouncing_ball", 1.0, Effect::kTrajectory},
      // event-driven
      // Free flight is a polynomial CVODE integrates exactly: tolerances show on the plank.
      {"event", "rtol", "1e-4", "plank_box", 0.3, Effect::kCvodeSteps},
      {"event", "atol", "1e-3", "plank_box", 0.3, Effect::kCvodeSteps},
      {"event", "method", "bdf", "bouncing_ball", 1.0, Effect::kCvodeSteps},
      // The pair of method = erk: Fehlberg 8(7) takes longer steps on the rocking flow.
      {"event",
       "erk_pair",
       "fehlberg8",
       "rocking_block",
       0.5,
       Effect::kCvodeSteps,
       {{"method", "erk"}}},
      // The fast restart (docs/engines.md): fewer CVODE steps per flight (CVODE's Adams: the
      // scenario's own method, own_erk, has neither setting).
      {"event",
       "startup_order",
       "2",
       "bouncing_ball",
       2.0,
       Effect::kCvodeSteps,
       {{"method", "adams"}}},
      // The same steps; the roots found on the dense output move the event times in their last
      // bits, and the samples after them.
      {"event",
       "dense_output_root_search",
       "true",
       "bouncing_ball",
       2.0,
       Effect::kTrajectory,
       {{"method", "adams"}}},
      {"event", "max_events", "2", "bouncing_ball", 2.0, Effect::kRunFails},
      {"event", "output_interval", "0.05", "bouncing_ball", 1.0, Effect::kSampleCount},
      {"event", "max_step", "1e-3", "bouncing_ball", 1.0, Effect::kCvodeSteps},
      // Post-impact speeds 3.78, 3.40, 3.06, 2.76 m/s: below 3 m/s from the 4th impact, which
      // ends the bouncing at once with a count of 1 and one impact later with the default 5.
      {"event",
       "zeno_impact_count",
       "1",
       "bouncing_ball",
       3.5,
       Effect::kEventCount,
       {{"zeno_velocity", "3"}}},
      {"event", "zeno_velocity", "2", "bouncing_ball", 9.0, Effect::kEventCount},
      {"event", "zeno_min_interval", "0.2", "bouncing_ball", 9.0, Effect::kEventCount},
      // The ball starts 0.9 m above the ground, outside a 1 cm margin: untracked until its gap
      // falls below 5 mm, where the approach guard restarts CVODE (one segment more).
      {"event", "contact_margin", "0.01", "bouncing_ball", 1.0, Effect::kCvodeSteps},
      // Balls 1 cm apart count as touching at the first impact: one simultaneous impact.
      {"event", "gap_tolerance", "0.02", "newtons_cradle", 0.5, Effect::kTrajectory},
      // The first bounce (3.78 m/s) counts as resting.
      {"event", "velocity_tolerance", "4", "bouncing_ball", 1.0, Effect::kTrajectory},
      // Coulomb rows of the planar mode problem have a zero diagonal, which PGS cannot take.
      {"event", "lcp_solver", "pgs", "sliding_block", 1.0, Effect::kRunFails},
      {"event",
       "friction_solver",
       "prox-jacobi",
       "sphere_spin",
       0.3,
       Effect::kNone,
       {},
       {},
       "the only spatial event scenario poses single-contact problems every solver solves "
       "exactly"},
      {"moreau",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"moreau",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
      // Box2D
      {"box2d", "dt", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      {"box2d", "velocity_iterations", "1", "box_pyramid", 0.2, Effect::kImpulses},
      // Position correction acts only on a penetration beyond the slop: the pyramid starts
      // touching (skins inside the boxes), and its settling makes such penetrations at a 10 ms
      // step, not at 1 ms.
      {"box2d",
       "position_iterations",
       "0",
       "box_pyramid",
       1.0,
       Effect::kTrajectory,
       {{"dt", "0.01"}}},
      {"box2d", "restitution_threshold", "10", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"box2d",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"box2d",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
      // Bullet
      {"bullet", "dt", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      {"bullet", "solver", "mlcp-dantzig", "sliding_block", 1.0, Effect::kTrajectory},
      {"bullet", "solver_iterations", "1", "box_pyramid", 0.2, Effect::kImpulses},
      {"bullet", "restitution_threshold", "10", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"bullet", "split_impulse", "false", "box_pyramid", 0.2, Effect::kTrajectory},
      {"bullet", "split_impulse_depth", "0.04", "box_pyramid", 0.2, Effect::kTrajectory},
      {"bullet",
       "erp",
       "0.8",
       "box_pyramid",
       0.2,
       Effect::kTrajectory,
       {{"split_impulse", "false"}}},
      {"bullet", "contact_breaking_threshold", "0.05", "bouncing_ball", 0.5,
       Effect::kContactRecords},
      {"bullet",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"bullet",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
      // ODE
      {"ode", "dt", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      // box_pyramid's file chooses quick (ODE's advice for large systems): exact changes the run.
      {"ode", "stepper", "exact", "box_pyramid", 0.2, Effect::kSolverIterations, {}, {{"rows", 3}}},
      {"ode",
       "quick_iterations",
       "1",
       "box_pyramid",
       0.2,
       Effect::kImpulses,
       {{"stepper", "quick"}},
       {{"rows", 3}}},
      {"ode", "friction", "box", "incline", 2.0, Effect::kTrajectory},
      {"ode", "erp", "0.8", "box_pyramid", 0.2, Effect::kTrajectory, {}, {{"rows", 3}}},
      {"ode", "cfm", "0.001", "box_pyramid", 0.2, Effect::kTrajectory, {}, {{"rows", 3}}},
      {"ode", "bounce_velocity", "10", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"ode", "max_contacts", "1", "box_pyramid", 0.2, Effect::kContactRecords, {}, {{"rows", 3}}},
      {"ode",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"ode",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
      // MuJoCo
      {"mujoco", "timestep", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      {"mujoco", "integrator", "rk4", "bouncing_ball", 0.6, Effect::kTrajectory},
      {"mujoco", "solver", "pgs", "box_pyramid", 0.2, Effect::kTrajectory, {}, {{"rows", 3}}},
      {"mujoco",
       "iterations",
       "1",
       "box_pyramid",
       0.2,
       Effect::kSolverIterations,
       {},
       {{"rows", 3}}},
      {"mujoco",
       "tolerance",
       "0.01",
       "box_pyramid",
       0.2,
       Effect::kSolverIterations,
       {},
       {{"rows", 3}}},
      {"mujoco", "cone", "pyramidal", "sliding_block", 1.0, Effect::kTrajectory},
      {"mujoco", "impratio", "100", "sliding_block", 1.0, Effect::kTrajectory},
      {"mujoco",
       "noslip_iterations",
       "20",
       "box_pyramid",
       0.2,
       Effect::kTrajectory,
       {},
       {{"rows", 3}}},
      {"mujoco", "solref_timeconst", "0.02", "bouncing_ball", 0.6, Effect::kTrajectory},
      {"mujoco", "solref_dampratio", "1", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"mujoco", "solimp_dmin", "0.5", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"mujoco", "solimp_dmax", "0.995", "bouncing_ball", 1.0, Effect::kTrajectory},
      {"mujoco",
       "solimp_width",
       "0.1",
       "bouncing_ball",
       1.0,
       Effect::kTrajectory,
       {{"solimp_dmin", "0.9"}}},
      {"mujoco",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"mujoco",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
      // Siconos (rows skipped where it is not built)
      {"siconos", "dt", "0.004", "bouncing_ball", 0.6, Effect::kSampleCount},
      {"siconos", "theta", "1", "bouncing_ball", 1.0, Effect::kTrajectory},
      // γ = 1 activates a step earlier first at the impact near t = 1.2 s.
      {"siconos", "gamma", "1", "bouncing_ball", 2.0, Effect::kTrajectory},
      // 0: the block placed on the ground leaves the contact set for its second step.
      {"siconos", "activation_threshold", "0", "sliding_block", 0.2, Effect::kTrajectory},
      {"siconos", "solver", "lemke", "sliding_block", 0.2, Effect::kTrajectory},
      // A loose tolerance or a single sweep: fewer solver iterations.
      {"siconos", "tolerance", "0.01", "sliding_block", 0.2, Effect::kSolverIterations},
      {"siconos", "max_iterations", "1", "sliding_block", 0.2, Effect::kSolverIterations},
      {"siconos", "scheme", "event_driven", "bouncing_ball", 1.0, Effect::kTrajectory},
      // Lsodar's tolerances move the event-driven trajectory by about themselves.
      {"siconos",
       "rtol",
       "1e-6",
       "bouncing_ball",
       1.0,
       Effect::kTrajectory,
       {{"scheme", "event_driven"}}},
      {"siconos",
       "atol",
       "1e-6",
       "bouncing_ball",
       1.0,
       Effect::kTrajectory,
       {{"scheme", "event_driven"}}},
      // Below round-off: the gap located at the first impact is already below −1e-20 m.
      {"siconos",
       "event_tolerance",
       "1e-20",
       "bouncing_ball",
       1.0,
       Effect::kRunFails,
       {{"scheme", "event_driven"}}},
      {"siconos",
       "impact_velocity",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_open_time", "100"}}},
      {"siconos",
       "impact_open_time",
       "100",
       "bouncing_ball",
       1.0,
       Effect::kImpactEvents,
       {{"impact_velocity", "100"}}},
  };
  return rows;
}

/// The run as `impactbench run` does it; nullopt when the engine stops with an error.
std::optional<engines::RunResult> run(const MatrixRow& row, bool with_setting,
                                      engines::RunOptions* resolved = nullptr) {
  const auto s = scenario::load_scenario_by_name(row.scenario, row.overrides);
  engines::SettingsRequest request;
  request.duration = row.duration;
  request.options = row.context;
  if (with_setting) request.options.emplace_back(row.key, row.value);
  const engines::RunOptions options = engines::resolve_run_options(row.engine, s, request);
  if (resolved) *resolved = options;
  try {
    return adapters::run_engine(row.engine, s, options);
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

std::vector<double> observe(const engines::RunResult& r, Effect effect) {
  std::vector<double> out;
  switch (effect) {
    case Effect::kTrajectory:
      for (const auto& sample : r.trajectory.samples)
        out.insert(out.end(), sample.q.data(), sample.q.data() + sample.q.size());
      break;
    case Effect::kSolverIterations: {
      double total = 0.0;
      for (const auto& step : r.steps) total += step.iterations;
      out.push_back(total);
      break;
    }
    case Effect::kImpulses: {
      double total = 0.0;
      for (const auto& step : r.steps)
        for (const auto& contact : step.contacts) total += contact.impulse_n;
      out.push_back(total);
      break;
    }
    case Effect::kContactRecords: {
      double total = 0.0;
      for (const auto& step : r.steps) total += static_cast<double>(step.contacts.size());
      out.push_back(total);
      break;
    }
    case Effect::kSampleCount:
      out.push_back(static_cast<double>(r.trajectory.samples.size()));
      break;
    case Effect::kEventCount:
      out.push_back(static_cast<double>(r.events.size()));
      break;
    case Effect::kImpactEvents: {
      double impacts = 0.0;
      for (const auto& event : r.events) impacts += event.kind == "impact" ? 1.0 : 0.0;
      out.push_back(impacts);
      break;
    }
    case Effect::kCvodeSteps:
      for (const auto& [name, value] : r.summary)
        if (name == "integrator steps (method)") out.push_back(std::stod(value));
      EXPECT_EQ(out.size(), 1u) << "no 'integrator steps (method)' in the event engine's summary";
      break;
    case Effect::kRunFails:
    case Effect::kRunCompletes:
    case Effect::kNone:
      break;
  }
  return out;
}

TEST(SettingsMatrix, EveryKeyOfEveryEngineHasARow) {
  for (const engines::EngineSettings* info : engines::engine_settings_catalog()) {
    for (const auto& key : info->keys) {
      int rows = 0;
      for (const auto& row : matrix()) rows += row.engine == info->engine && row.key == key.key;
      EXPECT_EQ(rows, 1) << info->engine << "." << key.key << " needs exactly one matrix row";
    }
  }
  for (const auto& row : matrix()) {
    const auto* info = engines::find_engine_settings(row.engine);
    ASSERT_NE(info, nullptr) << row.engine;
    EXPECT_TRUE(info->has_key(row.key)) << row.engine << "." << row.key << " is not a key";
  }
}

class SettingsMatrixRow : public testing::TestWithParam<MatrixRow> {};

TEST_P(SettingsMatrixRow, IsInForceFromTheCommandLineAndChangesTheRun) {
  const MatrixRow& row = GetParam();
  if (!adapters::find_engine(row.engine)->run)
    GTEST_SKIP() << row.engine << " is not built into this impactbench (optional)";
  engines::RunOptions baseline_options, options;
  const auto baseline = run(row, false, &baseline_options);
  const auto changed = run(row, true, &options);

  // In force: the canonical text of the value given, from the command line, and not what the
  // run without it has (else the row would show nothing).
  const auto info = engines::find_engine_settings(row.engine);
  const auto canonical =
      info->resolve({{row.key, row.value, engines::SettingSource::kCommandLine}}).in_force;
  const std::string expected = engines::setting_value(canonical, row.key);
  EXPECT_NE(engines::setting_value(baseline_options.settings, row.key), expected);
  if (changed) {
    bool found = false;
    for (const auto& setting : changed->settings)
      if (setting.key == row.key) {
        found = true;
        EXPECT_EQ(setting.value, expected);
        EXPECT_EQ(setting.source, engines::SettingSource::kCommandLine);
      }
    EXPECT_TRUE(found) << "the run's settings do not list " << row.key;
  }

  if (row.effect == Effect::kRunFails) {
    EXPECT_TRUE(baseline.has_value());
    EXPECT_FALSE(changed.has_value());
    return;
  }
  if (row.effect == Effect::kNone) {
    EXPECT_FALSE(row.no_effect_because.empty()) << "a row without an effect must say why";
    EXPECT_TRUE(baseline.has_value() && changed.has_value());
    return;
  }
  if (row.effect == Effect::kRunCompletes) {
    EXPECT_FALSE(baseline.has_value());
    EXPECT_TRUE(changed.has_value());
    return;
  }
  ASSERT_TRUE(baseline.has_value());
  ASSERT_TRUE(changed.has_value());
  const auto before = observe(*baseline, row.effect);
  const auto after = observe(*changed, row.effect);
  ASSERT_FALSE(before.empty());
  EXPECT_NE(before, after) << row.engine << "." << row.key << "=" << row.value
                           << " changed nothing observable";
}

// The expected direction where physics or the algorithm says which way it goes.
TEST(SettingsMatrix, LooserToleranceMeansFewerSweeps) {
  const MatrixRow tight{
      "moreau", "tolerance",    "1e-8", "disk_pile", 0.3, Effect::kSolverIterations,
      {},       {{"count", 20}}};
  MatrixRow loose = tight;
  loose.value = "1e-4";
  const auto a = run(tight, true), b = run(loose, true);
  ASSERT_TRUE(a && b);
  EXPECT_LT(observe(*b, Effect::kSolverIterations)[0], observe(*a, Effect::kSolverIterations)[0]);
}

std::string row_name(const testing::TestParamInfo<MatrixRow>& info) {
  std::string name = info.param.engine + "_" + info.param.key;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(AllKeys, SettingsMatrixRow, testing::ValuesIn(matrix()), row_name);

// Every flag an engine cannot use is refused with a message naming the engine and what it
// accepts; so is every key it does not have.
TEST(SettingsMatrix, FlagsAnEngineCannotUseAreRefused) {
  const auto ball = scenario::load_scenario_by_name("bouncing_ball");
  for (const engines::EngineSettings* info : engines::engine_settings_catalog()) {
    engines::SettingsRequest dt, tol, solver, unknown;
    dt.dt = 1e-3;
    tol.tolerance = 1e-6;
    solver.solver = "nsgs";
    unknown.options = {{"no_such_key", "1"}};
    const auto expect_refused = [&](const engines::SettingsRequest& request, bool accepted,
                                    const std::string& what) {
      if (accepted) {
        EXPECT_NO_THROW(engines::resolve_run_options(info->engine, ball, request)) << what;
        return;
      }
      try {
        engines::resolve_run_options(info->engine, ball, request);
        ADD_FAILURE() << info->engine << " accepted " << what;
      } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(info->engine + ":"), std::string::npos) << message;
        EXPECT_NE(message.find(info->title + " accepts"), std::string::npos) << message;
      }
    };
    expect_refused(dt, !info->dt_keys.empty(), "--dt");
    expect_refused(tol, !info->tolerance_keys.empty(), "--tol");
    // Bullet's, ODE's and MuJoCo's solver names are their own: nsgs is refused there as a
    // value, not as a flag.
    if (info->engine != "bullet" && info->engine != "ode" && info->engine != "mujoco")
      expect_refused(solver, static_cast<bool>(info->solver_key), "--solver");
    expect_refused(unknown, false, "--option no_such_key");
  }
  // The flags each engine takes, as documented in docs/settings.md.
  EXPECT_EQ(engines::find_engine_settings("event")->dt_keys.size(), 0u);
  EXPECT_EQ(engines::find_engine_settings("box2d")->tolerance_keys.size(), 0u);
  EXPECT_FALSE(engines::find_engine_settings("box2d")->solver_key);
  EXPECT_EQ(engines::find_engine_settings("bullet")->tolerance_keys.size(), 0u);
}

}  // namespace
}  // namespace impactbench
