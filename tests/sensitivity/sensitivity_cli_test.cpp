// `impactbench sensitivity --parameter-gains` against closed forms of the shipped scenarios, and
// its refusals of bad input (one line on stderr, the documented exit code, no file left).
//   sphere_spin: slip until t* = 2|c0|/(7μg), then rolling. The position at T > t* is
//     x(T) = v0 t* − μg t*²/2 ĉ + v*(T − t*) with v* = v0 − μg t* ĉ, so the t*-terms cancel and
//     ∂x(T)/∂μ = −(g t*²/2) ĉ; the rolling velocities v* = v0 − (2/7) c0 and ω* do not depend on
//     μ, and nothing depends on e (no impact).
//   bouncing_ball: first impact at t1 = v1/g, v1 = √(2g(h − R)); before the second,
//     z(T) = R + e v1 (T − t1) − g (T − t1)²/2, so ∂z/∂e = v1 (T − t1) and ∂ż/∂e = v1.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "tests/support/engines/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using impactbench::test_support::CliOutcome;

class SensitivityCli : public ::testing::Test {
 protected:
  CliOutcome run(const std::string& arguments) const {
    return impactbench::test_support::run_program(IMPACTBENCH_CLI, arguments, capture_.path(), "",
                                                  work_.path());
  }
  std::size_t file_count() const {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(work_.path())) ++count;
    return count;
  }
  /// The end-point "state" matrix of a gains file: (row, col) → value; absent entries are 0.
  std::map<std::pair<int, int>, double> end_point_state(const std::string& file) const {
    std::map<std::pair<int, int>, double> out;
    std::ifstream in(work_.path() / file);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("end_point,", 0) != 0) continue;
      std::stringstream fields(line);
      std::string f[9];
      for (std::string& field : f) std::getline(fields, field, ',');
      if (f[5] == "state") out[{std::stoi(f[6]), std::stoi(f[7])}] = std::stod(f[8]);
    }
    return out;
  }
  static double entry(const std::map<std::pair<int, int>, double>& m, int row, int col) {
    const auto it = m.find({row, col});
    return it == m.end() ? 0.0 : it->second;
  }

  impactbench::test_support::TemporaryDirectory work_{"sensitivity_cli_work"};
  impactbench::test_support::TemporaryDirectory capture_{"sensitivity_cli_capture"};
};

TEST_F(SensitivityCli, FrictionGainOfSphereSpinMatchesTheClosedForm) {
  const CliOutcome outcome = run("sensitivity sphere_spin --parameter-gains --out g.csv");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto gains = end_point_state("g.csv");
  // Tangent coordinates of one body: x y z, θ (3), v (3), ω (3), then μ (12) and e (13).
  const int mu = 12, e = 13;
  // The scenario's defaults: v0 = (2, 0.5), ω0 = (0, −10, 5), R = 0.1, μ = 0.3, g = 9.81.
  const double g = 9.81, friction = 0.3;
  const double c0x = 2.0 - 0.1 * -10.0, c0y = 0.5 + 0.1 * 0.0;
  const double c0 = std::hypot(c0x, c0y);
  const double t_star = 2 * c0 / (7 * friction * g);
  // Measured bound: the prediction through the end of a 3-D slip carries a floor of ~1e-7
  // relative (docs/sensitivity.md, slip → roll); 1e-6 of the entries' scale (|∂x/∂μ| ≈ 0.43,
  // rolling speeds ≈ 2 m/s and 22 rad/s) leaves room for it.
  const double scale = g * t_star * t_star / 2;
  EXPECT_NEAR(entry(gains, 0, mu), -scale * c0x / c0, 1e-6 * scale);
  EXPECT_NEAR(entry(gains, 1, mu), -scale * c0y / c0, 1e-6 * scale);
  EXPECT_NEAR(entry(gains, 2, mu), 0.0, 1e-6 * scale);
  for (int row = 6; row < 9; ++row) EXPECT_NEAR(entry(gains, row, mu), 0.0, 2e-6) << row;
  const double omega_scale = 5 * c0 / (7 * 0.1);
  for (int row = 9; row < 12; ++row)
    EXPECT_NEAR(entry(gains, row, mu), 0.0, 1e-6 * omega_scale) << row;
  for (int row = 0; row < 12; ++row) EXPECT_EQ(entry(gains, row, e), 0.0) << row;
  EXPECT_EQ(entry(gains, mu, mu), 1.0);
  EXPECT_EQ(entry(gains, e, e), 1.0);
}

TEST_F(SensitivityCli, RestitutionGainOfABounceMatchesTheClosedForm) {
  const double T = 0.8;  // after the first impact (0.43 s), before the second (1.2 s)
  const CliOutcome outcome =
      run("sensitivity bouncing_ball --parameter-gains --duration 0.8 --out b.csv");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto gains = end_point_state("b.csv");
  // Planar tangent coordinates: x y θ vx vy ω, then μ (6) and e (7).
  const double g = 9.81, v1 = std::sqrt(2 * g * (1.0 - 0.1)), t1 = v1 / g;
  // The flights are quadratic in t (RK4 is exact on them) and the impact time is located to the
  // engine's tolerance 1e-12: 1e-9 bounds both with room.
  EXPECT_NEAR(entry(gains, 1, 7), v1 * (T - t1), 1e-9);
  EXPECT_NEAR(entry(gains, 4, 7), v1, 1e-9);
  for (int row = 0; row < 6; ++row) EXPECT_EQ(entry(gains, row, 6), 0.0) << row;  // μ = 0, no slip
}

TEST_F(SensitivityCli, BadInputIsRefusedInOneLineWithoutOutput) {
  const struct {
    std::string arguments;
    int exit_code;
    std::string message;
  } cases[] = {
      {"--epsilon 0", 2, "--epsilon: must be a finite number > 0, got '0'"},
      {"--epsilon -1e-3", 2, "--epsilon: must be a finite number > 0, got '-1e-3'"},
      {"--epsilon nan", 2, "--epsilon: must be a finite number > 0, got 'nan'"},
      {"--epsilon inf", 2, "--epsilon: must be a finite number > 0, got 'inf'"},
      {"--tol 0", 2, "--tol: must be a finite number > 0, got '0'"},
      {"--set restitution=nan", 2, "--set restitution: 'nan' is not a finite number"},
  };
  for (const auto& c : cases) {
    const CliOutcome outcome = run("sensitivity bouncing_ball --duration 0.5 --parameter-gains " +
                                   c.arguments + " --out g.csv --prediction p.csv");
    EXPECT_EQ(outcome.exit_code, c.exit_code) << c.arguments << ": " << outcome.err;
    EXPECT_NE(outcome.err.find(c.message), std::string::npos) << outcome.err;
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
    EXPECT_EQ(file_count(), 0u) << c.arguments << " left a file";
  }
  // A scenario the linearisation cannot follow: sphere_pile lists no event-driven engine.
  const CliOutcome pile = run("sensitivity sphere_pile --duration 0.2 --out g.csv");
  EXPECT_EQ(pile.exit_code, 1) << pile.err;
  EXPECT_NE(pile.err.find("sensitivity needs the event-driven engine"), std::string::npos)
      << pile.err;
  EXPECT_EQ(pile.err.find('\n'), pile.err.size() - 1) << pile.err;
  EXPECT_EQ(file_count(), 0u);
}

}  // namespace
