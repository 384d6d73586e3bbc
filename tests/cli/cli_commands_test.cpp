// The impactbench program as users call it: list and describe output, and for run every
// failure as one line on stderr with the documented exit code and no output file.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/engines/cli_runner.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace {

namespace fs = std::filesystem;

using Outcome = impactbench::test_support::CliOutcome;
using impactbench::test_support::read_text;

class Cli : public ::testing::Test {
 protected:
  /// Runs `[environment] impactbench <arguments>` through the shell.
  Outcome run(const std::string& arguments, const std::string& environment = "") const {
    return impactbench::test_support::run_program(IMPACTBENCH_CLI, arguments, capture_.path(),
                                                  environment);
  }

  /// A failed command: the expected exit code, nothing on stdout, one line on stderr that
  /// contains `message`, and no file written into the work directory.
  void expect_failure(const Outcome& outcome, int exit_code, const std::string& message) const {
    EXPECT_EQ(outcome.exit_code, exit_code) << outcome.err;
    EXPECT_TRUE(outcome.out.empty()) << outcome.out;
    ASSERT_FALSE(outcome.err.empty());
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;  // one line
    EXPECT_EQ(outcome.err.rfind("impactbench: ", 0), 0u) << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_TRUE(fs::is_empty(directory_)) << "a failed run left a file";
  }

  std::string out_option() const { return "--out '" + (directory_ / "traj.csv").string() + "'"; }

  impactbench::test_support::TemporaryDirectory work_{"impactbench_cli"};
  impactbench::test_support::TemporaryDirectory capture_{"impactbench_capture"};
  const fs::path directory_ = work_.path();
};

/// The number printed right after `label` in `text` (NaN when the label is missing).
double number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

TEST_F(Cli, ListPrintsTheScenarioNamesOnePerLine) {
  const Outcome outcome = run("list");
  EXPECT_EQ(outcome.exit_code, 0);
  EXPECT_EQ(outcome.err, "");
  EXPECT_EQ(outcome.out,
            "bouncing_ball\nbox_pyramid\ncube_toss\ndisk_pile\nincline\nnewtons_cradle\nplank_box\n"
            "rocking_block\nsliding_block\nsphere_pile\nsphere_spin\n");
}

TEST_F(Cli, ListFollowsTheScenarioDirectoryVariable) {
  const Outcome outcome =
      run("list", "IMPACTBENCH_SCENARIOS='" IMPACTBENCH_TEST_DATA_DIR "/scenarios_bad'");
  EXPECT_EQ(outcome.exit_code, 0);
  EXPECT_NE(outcome.out.find("missing_mass\n"), std::string::npos);
  EXPECT_EQ(outcome.out.find("bouncing_ball"), std::string::npos);
}

TEST_F(Cli, DescribeShowsParametersEnginesAndAnalyticValues) {
  const Outcome outcome = run("describe bouncing_ball");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string& text = outcome.out;
  for (const char* line :
       {"name: bouncing_ball\n", "dimension: planar\n", "system: rigid_bodies\n",
        "engines: moreau, event, box2d, bullet, ode, mujoco, siconos\n", "dt: 0.001 s\n",
        "tolerance: 1e-10\n", "bodies: ball\n", "planes: ground\n", "parameters:\n", "analytic:\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line;
  for (const char* parameter :
       {"g           = 9.81 m/s^2", "radius      = 0.1 m", "mass        = 1 kg",
        "height      = 1 m", "restitution = 0.9 1", "friction    = 0 1"})
    EXPECT_NE(text.find(parameter), std::string::npos) << parameter;
  // t_inf = t1 (1 + e)/(1 - e), t1 = sqrt(2 (h - r)/g), printed to be read back exactly; the
  // program evaluates the file's formula, so it agrees with this one to a few roundings.
  const double t_inf = std::sqrt(2 * 0.9 / 9.81) * 1.9 / 0.1;
  EXPECT_NEAR(number_after(text, "t_inf            = "), t_inf, 1e-14 * t_inf) << text;
  EXPECT_NEAR(number_after(text, "duration: "), 1.2 * t_inf, 1e-14 * t_inf) << text;
  EXPECT_NE(text.find("impact_time(k)"), std::string::npos);
}

// Siconos is optional at build time: a build without it knows the name (scenarios list it) but
// refuses to run it as a usage error; a build with it runs it.
TEST_F(Cli, AnOptionalEngineRunsWhereBuiltAndIsRefusedElsewhere) {
  const bool built = static_cast<bool>(impactbench::adapters::find_engine("siconos")->run);
  const Outcome outcome = run("run bouncing_ball --engine siconos --duration 0.1 " + out_option());
  if (built) {
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_TRUE(fs::exists(directory_ / "traj.csv"));
  } else {
    expect_failure(outcome, 2, "engine 'siconos' is not built into this impactbench");
    // compare leaves it out unless asked for, and refuses it when asked for.
    expect_failure(run("compare bouncing_ball --engines siconos --no-plots --out '" +
                       (directory_ / "compared").string() + "'"),
                   2, "engine 'siconos' is not built into this impactbench");
  }
}

TEST_F(Cli, DescribeWithOverridesShowsValueAndDefault) {
  const Outcome outcome = run("describe sliding_block --set v0=3 --set friction=0.25");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("v0          = 3 m/s (default 2)"), std::string::npos) << outcome.out;
  // stop_time = v0/(mu g) with the overridden values.
  const double stop_time = 3 / (0.25 * 9.81);
  EXPECT_NEAR(number_after(outcome.out, "stop_time            = "), stop_time, 1e-14 * stop_time)
      << outcome.out;
}

TEST_F(Cli, DescribeErrors) {
  expect_failure(run("describe no_such_scenario"), 1, "no such scenario (available: bouncing_ball");
  expect_failure(run("describe"), 2, "scenario is required");
  expect_failure(run("describe negative_mass",
                     "IMPACTBENCH_SCENARIOS='" IMPACTBENCH_TEST_DATA_DIR "/scenarios_bad'"),
                 1, "negative_mass.toml:22: bodies[0].mass: must be > 0");
}

TEST_F(Cli, RunWritesTrajectoryEventsAndSummary) {
  const fs::path events = directory_ / "ev.csv";
  const Outcome event =
      run("run incline --engine event --tol 1e-9 --duration 1.5 --set angle=15 "
          "--events '" +
          events.string() + "' " + out_option());
  ASSERT_EQ(event.exit_code, 0) << event.err;
  EXPECT_NE(event.out.find("event on incline"), std::string::npos) << event.out;
  EXPECT_EQ(read_text(events).rfind("t,contact,kind,from_mode,to_mode,impulse_n,impulse_t\n", 0),
            0u);
  EXPECT_EQ(read_text(directory_ / "traj.csv").rfind("t,block.x,block.y,block.theta,", 0), 0u);
  const Outcome bullet = run("run sphere_spin --engine bullet --duration 0.05 " + out_option());
  EXPECT_EQ(bullet.exit_code, 0) << bullet.err;
  EXPECT_NE(bullet.out.find("bullet on sphere_spin"), std::string::npos);
  const Outcome moreau =
      run("run sliding_block --engine moreau --solver lemke --duration 0.1 " + out_option());
  EXPECT_EQ(moreau.exit_code, 0) << moreau.err;
  EXPECT_NE(moreau.out.find("setting solver"), std::string::npos) << moreau.out;
  fs::remove(directory_ / "traj.csv");
  fs::remove(events);
  expect_failure(run("run sliding_block --engine moreau --solver simplex " + out_option()), 2,
                 "moreau: setting 'solver' must be one of");
}

TEST_F(Cli, RunRejectsBadInputBeforeTheEngine) {
  const std::string out = out_option();
  expect_failure(
      run("run bouncing_ball --engine moreau --set heigth=2 " + out), 1,
      "--set heigth: unknown parameter (valid: g, radius, mass, height, restitution, friction)");
  expect_failure(run("run bouncing_ball --engine moreau --set restitution=1.5 " + out), 1,
                 "material.restitution: restitution must be in [0, 1] (got 1.5)");
  expect_failure(run("run bouncing_ball --engine moreau --set height " + out), 2,
                 "--set expects name=value, got 'height'");
  expect_failure(run("run sphere_spin --engine box2d " + out), 1,
                 "scenario 'sphere_spin' cannot be run by engine 'box2d'");
  expect_failure(run("run bouncing_ball --engine physx " + out), 2, "--engine");
  expect_failure(run("run bouncing_ball --engine moreau --dt -1 " + out), 2,
                 "must be a finite number > 0, got '-1'");
  expect_failure(run("run bouncing_ball --engine moreau --dt 20 " + out), 2,
                 "exceeds the duration");
  expect_failure(run("run bouncing_ball --engine moreau --tol nan " + out), 2, "--tol");
  expect_failure(run("run bouncing_ball --engine moreau"), 2, "--out is required");
  expect_failure(run("run bouncing_ball --engine moreau --out /no/such/dir/t.csv"), 1,
                 "directory /no/such/dir does not exist");
  expect_failure(run("run no_such --engine moreau " + out), 1, "no such scenario");
}

TEST_F(Cli, UnknownSubcommandIsAUsageError) {
  expect_failure(run("fly"), 2, "fly");
  expect_failure(run(""), 2, "subcommand is required");
}

TEST_F(Cli, SolveReportsStatusIterationsResidualAndTime) {
  const Outcome outcome =
      run("solve '" IMPACTBENCH_TEST_DATA_DIR "/lcp/chain_5_sparse.lcp' --solver lemke");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  for (const char* line :
       {"LCP, n = 5 (sparse)", "status   converged", "iterations ", "residual ", "time "})
    EXPECT_NE(outcome.out.find(line), std::string::npos) << line << "\n" << outcome.out;
  const auto at = outcome.out.find("residual ");
  EXPECT_LT(std::stod(outcome.out.substr(at + 9)), 1e-10);
}

TEST_F(Cli, SolveRejectsBadFilesAndSolvers) {
  const fs::path bad = directory_ / "bad.lcp";
  {
    std::ofstream out(bad);
    out << "lcp 2 dense\n1 2\n1 0\n0 x\n";
  }
  const Outcome malformed = run("solve '" + bad.string() + "' --solver lemke");
  EXPECT_EQ(malformed.exit_code, 1);
  EXPECT_NE(malformed.err.find(bad.string() + ":4"), std::string::npos) << malformed.err;
  fs::remove(bad);
  expect_failure(run("solve '" IMPACTBENCH_TEST_DATA_DIR "/lcp/chain_5_sparse.lcp' --solver nsgs"),
                 2, "is not a LCP solver (lemke");
  expect_failure(run("solve '" + (directory_ / "missing.h5").string() + "' --solver nsgs"), 1,
                 "no such file");
}

// The run summary prints the figures of metrics.csv under the same names.
TEST_F(Cli, RunSummaryPrintsTheRunFigures) {
  for (const std::string engine : {"moreau", "box2d"}) {
    const Outcome outcome =
        run("run bouncing_ball --engine " + engine + " --dt 0.001 --duration 0.1 " + out_option());
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    for (const char* name : {"engine_cpu_seconds", "record_cpu_seconds", "wall_seconds",
                             "mean_contacts", "max_penetration"})
      EXPECT_NE(outcome.out.find(std::string("\n  ") + name + " "), std::string::npos)
          << name << " in\n"
          << outcome.out;
    EXPECT_NE(outcome.out.find("\n  steps                100\n"), std::string::npos) << outcome.out;
    EXPECT_NE(outcome.out.find(engine == "moreau"
                                   ? "\n  unconverged_steps    0\n"
                                   : "\n  unconverged_steps    - (Box2D runs a fixed number"),
              std::string::npos)
        << outcome.out;
    fs::remove(directory_ / "traj.csv");
  }
}

TEST_F(Cli, CompareWritesOneMetricsRowPerEngine) {
  const fs::path out = directory_ / "cmp";
  const Outcome outcome =
      run("compare sliding_block --engines box2d,bullet --duration 0.6 "
          "--no-plots --out '" +
          out.string() + "'");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::istringstream metrics(read_text(out / "metrics.csv"));
  std::string header, box2d, bullet, extra;
  std::getline(metrics, header);
  std::getline(metrics, box2d);
  std::getline(metrics, bullet);
  EXPECT_FALSE(std::getline(metrics, extra));
  EXPECT_EQ(header.rfind("engine,engine_cpu_seconds,record_cpu_seconds,wall_seconds,steps,"
                         "unconverged_steps,mean_contacts,",
                         0),
            0u)
      << header;
  EXPECT_NE(header.find("stop_distance_error"), std::string::npos) << header;
  EXPECT_EQ(header.substr(header.size() - 14), ",note,settings") << header;
  // Fixed-iteration engines: steps = duration / dt, unconverged_steps empty and a note why.
  const double dt = 1e-3;  // sliding_block's default step
  for (const std::string* row : {&box2d, &bullet}) {
    std::vector<std::string> cells;
    std::istringstream split(*row);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 7u) << *row;
    EXPECT_EQ(std::stod(cells[4]), std::round(0.6 / dt)) << *row;
    EXPECT_EQ(cells[5], "") << *row;
    EXPECT_NE(cells[cells.size() - 2].find("fixed number"), std::string::npos) << *row;
  }
  EXPECT_EQ(box2d.rfind("box2d,", 0), 0u);
  EXPECT_EQ(bullet.rfind("bullet,", 0), 0u);
  for (const char* file : {"box2d_trajectory.csv", "bullet_events.csv"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
}

// The value of `setting KEY VALUE (SOURCE)` in a run summary, parsed back as a number; NaN
// when the summary has no such line.
double summary_setting(const std::string& summary, const std::string& key, std::string* source) {
  const std::string prefix = "  setting " + key + " ";
  const auto at = summary.find(prefix);
  if (at == std::string::npos) return std::nan("");
  const auto end = summary.find('\n', at);
  const std::string rest = summary.substr(at + prefix.size(), end - at - prefix.size());
  const auto space = rest.find(' ');
  if (source) *source = rest.substr(space + 1);
  return std::stod(rest.substr(0, space));
}

TEST_F(Cli, RunSummaryGivesEverySettingWithItsSource) {
  const std::string base = "run disk_pile --engine moreau --set count=20 --duration 0.3 ";
  const Outcome loose = run(base + "--tol 1e-3 " + out_option());
  ASSERT_EQ(loose.exit_code, 0) << loose.err;
  std::string source;
  EXPECT_EQ(summary_setting(loose.out, "tolerance", &source), 1e-3) << loose.out;
  EXPECT_EQ(source, "(command line)");
  EXPECT_NE(loose.out.find("  setting tolerance 0.001 (command line)\n"), std::string::npos);
  EXPECT_EQ(summary_setting(loose.out, "dt", &source), 1e-3);
  EXPECT_EQ(source, "(scenario)");
  EXPECT_EQ(summary_setting(loose.out, "duration", &source), 0.3);
  EXPECT_EQ(source, "(command line)");
  for (const char* key :
       {"theta", "solver", "max_iterations", "on_failure", "forces", "contact_margin",
        "cone_facets", "activation_horizon", "activation_tolerance"})
    EXPECT_NE(loose.out.find(std::string("  setting ") + key + " "), std::string::npos) << key;
  EXPECT_EQ(loose.out.find("0.000000"), std::string::npos) << loose.out;
  // The scenario's own tolerance when none is given (its [settings.moreau] table: 1e-4);
  // a looser --tol makes fewer sweeps than it.
  const Outcome nominal = run(base + out_option());
  ASSERT_EQ(nominal.exit_code, 0) << nominal.err;
  EXPECT_EQ(summary_setting(nominal.out, "tolerance", &source), 1e-4);
  EXPECT_EQ(source, "(scenario)");
  const auto sweeps = [](const std::string& out) {
    const auto at = out.find("  solver_iterations ");
    return at == std::string::npos ? -1.0 : std::stod(out.substr(at + 20));
  };
  EXPECT_GT(sweeps(loose.out), 0.0);
  EXPECT_LT(sweeps(loose.out), sweeps(nominal.out));
  // --option outranks the flag; ENGINE.key applies to the engine of `run`.
  const Outcome option =
      run(base + "--tol 1e-4 --option moreau.tolerance=1e-6 --option theta=1 " + out_option());
  ASSERT_EQ(option.exit_code, 0) << option.err;
  EXPECT_EQ(summary_setting(option.out, "tolerance", &source), 1e-6);
  EXPECT_EQ(summary_setting(option.out, "theta", &source), 1.0);
  EXPECT_EQ(source, "(command line)");
}

TEST_F(Cli, RunRefusesAnUnknownFlowIntegratorOrRungeKuttaPair) {
  const std::string out = out_option();
  expect_failure(run("run bouncing_ball --engine event --option method=rk4 " + out), 2,
                 "event: setting 'method' must be one of bdf, adams, erk or own_erk, got 'rk4'");
  expect_failure(run("run bouncing_ball --engine event --option erk_pair=verner8 " + out), 2,
                 "event: setting 'erk_pair' must be one of dopri5, verner6 or fehlberg8, got "
                 "'verner8'");
}

TEST_F(Cli, RunRefusesAStartupOrderOrRootSearchSwitchOutOfRange) {
  const std::string out = out_option();
  const std::string run_event = "run bouncing_ball --engine event --option ";
  expect_failure(run(run_event + "startup_order=13 " + out), 2,
                 "event: setting 'startup_order' must be a whole number in [0, 12], got '13'");
  expect_failure(run(run_event + "startup_order=-1 " + out), 2,
                 "event: setting 'startup_order' must be a whole number in [0, 12], got '-1'");
  expect_failure(run(run_event + "startup_order=2.5 " + out), 2,
                 "event: setting 'startup_order' must be a whole number, got '2.5'");
  expect_failure(run(run_event + "dense_output_root_search=maybe " + out), 2,
                 "event: setting 'dense_output_root_search' must be 0/1 or true/false, got "
                 "'maybe'");
}

TEST_F(Cli, RunRefusesSettingsTheEngineCannotUse) {
  const std::string out = out_option();
  expect_failure(run("run bouncing_ball --engine box2d --solver nsgs " + out), 2,
                 "box2d: --solver is not a setting of Box2D (Box2D accepts --dt and --option "
                 "KEY=VALUE with KEY one of dt, velocity_iterations, position_iterations, "
                 "restitution_threshold, impact_velocity and impact_open_time)");
  expect_failure(run("run bouncing_ball --engine box2d --tol 1e-6 " + out), 2,
                 "box2d: --tol is not a setting of Box2D");
  expect_failure(run("run bouncing_ball --engine bullet --tol 1e-6 " + out), 2,
                 "bullet: --tol is not a setting of Bullet");
  expect_failure(run("run bouncing_ball --engine event --dt 1e-3 " + out), 2,
                 "event: --dt is not a setting of the event-driven engine");
  expect_failure(run("run bouncing_ball --engine event --solver bogus " + out), 2,
                 "event: setting 'solver' must be an LCP solver (lemke");
  expect_failure(run("run bouncing_ball --engine event --option lcp_solver=bogus " + out), 2,
                 "event: setting 'lcp_solver' must be one of lemke");
  expect_failure(run("run bouncing_ball --engine bullet --solver nsgs " + out), 2,
                 "bullet: setting 'solver' must be one of si or mlcp-dantzig, got 'nsgs'");
  expect_failure(run("run bouncing_ball --engine bullet --option split_impulse=2 " + out), 2,
                 "bullet: setting 'split_impulse' must be 0/1 or true/false, got '2'");
  expect_failure(run("run bouncing_ball --engine box2d --option velocity_iterations=1e9 " + out), 2,
                 "setting 'velocity_iterations' must be a whole number in [1, 10000], got '1e9'");
  expect_failure(run("run bouncing_ball --engine moreau --option max_iterations=1e10 " + out), 2,
                 "must be a whole number in [1, 1000000], got '1e10'");
  expect_failure(run("run bouncing_ball --engine moreau --option max_iterations=2.5 " + out), 2,
                 "must be a whole number, got '2.5'");
  expect_failure(run("run bouncing_ball --engine moreau --option theta=-0 " + out), 2,
                 "setting 'theta' must be in [0.5, 1], got '-0'");
  expect_failure(run("run bouncing_ball --engine moreau --option theta=nan " + out), 2,
                 "setting 'theta' must be a finite number, got 'nan'");
  expect_failure(run("run bouncing_ball --engine moreau --option bogus=1 " + out), 2,
                 "moreau: setting 'bogus' is unknown (Moreau–Jean accepts --dt, --tol, --solver");
  expect_failure(
      run("run bouncing_ball --engine moreau --option box2d.velocity_iterations=8 " + out), 2,
      "engine 'box2d' is not run here");
  expect_failure(run("run bouncing_ball --engine moreau --option physx.theta=1 " + out), 2,
                 "unknown engine 'physx'");
  expect_failure(
      run("run bouncing_ball --engine moreau --option theta=1 --option theta=0.6 " + out), 2,
      "--option theta given twice");
  expect_failure(run("run bouncing_ball --engine moreau --option theta " + out), 2,
                 "is not [ENGINE.]key=value");
  expect_failure(run("run bouncing_ball --engine moreau --option moreau.=1 " + out), 2,
                 "names no key");
  expect_failure(run("run bouncing_ball --engine moreau --dt 1 --duration 0.5 " + out), 2,
                 "moreau: step dt = 1 (command line) exceeds the duration 0.5 (command line)");
  // No error prints a 300-digit range or -0.000000.
  const Outcome tol = run("run bouncing_ball --engine moreau --tol 0 " + out);
  expect_failure(tol, 2, "must be a finite number > 0, got '0'");
  EXPECT_LT(tol.err.size(), 200u) << tol.err;
}

TEST_F(Cli, CompareTakesPerEngineOptionsAndRefusesBareOnes) {
  const fs::path dir = directory_ / "cmp";
  const std::string base =
      "compare bouncing_ball --engines moreau,box2d --duration 0.05 "
      "--no-plots --out '" +
      dir.string() + "' ";
  const Outcome ok = run(base + "--option moreau.theta=1 --option box2d.velocity_iterations=8");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const std::string metrics = read_text(dir / "metrics.csv");
  EXPECT_NE(metrics.find(",settings\n"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("theta=1 (command line)"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("velocity_iterations=8 (command line)"), std::string::npos);
  EXPECT_NE(metrics.find("tolerance=1e-10 (scenario)"), std::string::npos);
  EXPECT_NE(metrics.find("duration=0.05 (command line)"), std::string::npos);
  fs::remove_all(dir);
  expect_failure(run(base + "--option theta=1"), 2, "must name its engine");
  expect_failure(run(base + "--option event.rtol=1e-6"), 2, "engine 'event' is not run here");
  expect_failure(run(base + "--option box2d.velocity_iterations=1e9"), 2,
                 "must be a whole number in [1, 10000]");
  expect_failure(run(base + "--option moreau.bogus=1"), 2, "moreau: setting 'bogus' is unknown");
  const std::string plain = "compare bouncing_ball --no-plots --out '" + dir.string() + "' ";
  expect_failure(run(plain + "--dt nan"), 2, "--dt");
  expect_failure(run(plain + "--duration nan"), 2, "--duration");
  expect_failure(run(plain + "--dt 1 --duration 0.05"), 2, "exceeds the duration 0.05");
  expect_failure(run("compare bouncing_ball --engines event --dt 1e-3 --no-plots --out '" +
                     dir.string() + "'"),
                 2, "none of the engines compared has a step");
}

TEST_F(Cli, DescribePrintsEachEnginesSettingsInForce) {
  const Outcome plank = run("describe plank_box");
  ASSERT_EQ(plank.exit_code, 0) << plank.err;
  for (const char* line :
       {"settings of moreau:\n", "  solver = nsgs (default)\n",
        "  forces = linearly-implicit (scenario)\n", "  tolerance = 1e-10 (scenario)\n",
        "  theta = 0.5 (default)\n", "settings of event:\n", "  rtol = 1e-10 (scenario)\n"})
    EXPECT_NE(plank.out.find(line), std::string::npos) << line << plank.out;
}

TEST_F(Cli, ScenarioEngineSettingsAreCheckedOnLoad) {
  const fs::path scenarios = directory_ / "scenarios";
  fs::create_directories(scenarios);
  // The shipped file, wherever the program finds it (describe names it): a scenario without
  // settings tables of its own, so that `settings = 1` is the only settings entry.
  const std::string described = run("describe incline").out;
  const auto file_at = described.find("file: ") + 6;
  const std::string incline =
      read_text(described.substr(file_at, described.find('\n', file_at) - file_at));
  ASSERT_NE(incline.find("name = \"incline\""), std::string::npos);
  // Tables go at the end; top-level keys must come before the first table.
  const auto write = [&](const std::string& table) {
    if (table.rfind("settings =", 0) == 0)
      std::ofstream(scenarios / "incline.toml") << table << incline;
    else
      std::ofstream(scenarios / "incline.toml") << incline << "\n" << table;
  };
  const std::string env = "IMPACTBENCH_SCENARIOS='" + scenarios.string() + "'";
  const std::string out = "--out '" + (directory_ / "t.csv").string() + "' ";
  const auto line_of_table = std::to_string(std::count(incline.begin(), incline.end(), '\n') + 3);
  const auto refused = [&](const std::string& table, const std::string& message) {
    write(table);
    const Outcome outcome = run("describe incline", env);
    EXPECT_EQ(outcome.exit_code, 1) << table;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << table << "\n" << outcome.err;
    EXPECT_TRUE(outcome.out.empty());
  };
  refused("[settings.moreau]\nbogus = 1\n",
          "incline.toml:" + line_of_table + ": settings.moreau.bogus: is unknown");
  refused("[settings.moreau]\ntheta = 2\n", "settings.moreau.theta: must be in [0.5, 1]");
  refused("[settings.moreau]\ndt = 100\n", "settings.moreau.dt: step 100 exceeds the duration");
  refused("[settings.moreau]\ntheta = [1]\n", "expected a number, a string or true/false");
  refused("[settings.physx]\ntheta = 1\n", "settings.physx: unknown engine 'physx'");
  refused("[settings]\nmoreau = 1\n", "settings.moreau: expected a table");
  refused("settings = 1\n", "settings: expected a table");
  write(
      "[settings.moreau]\ntheta = 1\nsolver = \"lemke\"\n[settings.bullet]\n"
      "split_impulse = false\n");
  const Outcome ok = run("run incline --engine moreau --duration 0.05 " + out, env);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("  setting theta 1 (scenario)\n"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("  setting solver lemke (scenario)\n"), std::string::npos);
  // The command line outranks the scenario.
  const Outcome over = run("run incline --engine moreau --duration 0.05 --solver nsgs " + out, env);
  ASSERT_EQ(over.exit_code, 0) << over.err;
  EXPECT_NE(over.out.find("  setting solver nsgs (command line)\n"), std::string::npos);
  const Outcome bullet = run("run incline --engine bullet --duration 0.05 " + out, env);
  ASSERT_EQ(bullet.exit_code, 0) << bullet.err;
  EXPECT_NE(bullet.out.find("  setting split_impulse false (scenario)\n"), std::string::npos);
}

TEST_F(Cli, PositiveNumbersAreRefusedInOneShortLine) {
  const std::string out = "--out '" + (directory_ / "g.csv").string() + "'";
  for (const std::string& command :
       {"sensitivity bouncing_ball --duration nan " + out,
        "sensitivity bouncing_ball --tol -0 " + out,
        std::string("solve '" IMPACTBENCH_TEST_DATA_DIR "/lcp/chain_5_sparse.lcp' --solver "
                    "lemke --tol 0")}) {
    const Outcome outcome = run(command);
    expect_failure(outcome, 2, "must be a finite number > 0, got '");
    EXPECT_LT(outcome.err.size(), 160u) << outcome.err;  // no 300-digit range
  }
}

}  // namespace
