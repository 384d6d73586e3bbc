// Every registered friction solver that can run a scenario gives the same Moreau–Jean
// trajectory, to the tolerance it reaches, on bouncing_ball, sliding_block and plank_box (all
// planar: the LCP conversion is exact there). The reference is lemke (pivoting, exact up to
// round-off); positions and velocities are compared at every step. Iterative solvers run with
// on_failure = warn: on the plank–box's near-redundant two-corner contact their residual can
// stall near 1e-6 for a few steps, and the bound below is 1e-9 plus the worst residual of the
// run. A solver that reports it cannot handle the problem at all (status singular) is listed
// and skipped.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "test_utilities/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

struct Scenario {
  std::string name;
  std::unique_ptr<model::LagrangianSystem<double>> system;
  Eigen::VectorXd q0, v0;
  double duration = 0.0;
  ForceTreatment forces = ForceTreatment::kExplicit;
};

std::vector<Scenario> scenarios() {
  std::vector<Scenario> list;
  {
    testing::PlanarWorldSpec spec;
    spec.bodies = {testing::disk("ball", 0.1, 1.0)};
    spec.material = {0.0, 0.9};
    list.push_back({"bouncing_ball",
                    testing::make_planar_world(testing::PlanarKind::kProjectSystem, spec),
                    Eigen::Vector3d(0, 1, 0), Eigen::Vector3d::Zero(), 2.0});
  }
  {
    testing::PlanarWorldSpec spec;
    spec.bodies = {testing::box("block", 0.2, 0.2, 1.0)};
    spec.material = {0.5, 0.0};
    list.push_back({"sliding_block",
                    testing::make_planar_world(testing::PlanarKind::kProjectSystem, spec),
                    Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(2, 0, 0), 0.6});
  }
  {
    model::PlankBoxParameters p;
    p.restitution = 0.3;
    auto system = std::make_unique<model::PlankBoxSystem<double>>(p);
    // Box 5 cm above the plank surface at 0.6 m from the hinge, tilted by 0.3 rad.
    const double phi = -0.0485;
    const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
    const double lowest = 0.5 * p.box_height * std::cos(0.3) + 0.5 * p.box_length * std::sin(0.3);
    const Eigen::Vector2d c = 0.6 * e1 + (0.5 * p.plank_thickness + lowest + 0.05) * e2;
    list.push_back({"plank_box", std::move(system), Eigen::Vector4d(c.x(), c.y(), phi + 0.3, phi),
                    Eigen::Vector4d::Zero(), 1.0, ForceTreatment::kLinearlyImplicit});
  }
  return list;
}

struct Trajectory {
  std::vector<Eigen::VectorXd> states;
  bool ok = false;
  bool unsupported = false;  ///< some step reported kSingular
  double worst_residual = 0.0;
  int failures = 0;
  std::string message;
};

Trajectory run(const Scenario& s, const std::string& solver) {
  MoreauJeanOptions options;
  options.solver = solver;
  options.tolerance = 1e-12;
  options.max_iterations = 20000;
  options.forces = s.forces;
  options.record_impulses = false;
  options.on_failure = OnFailure::kWarn;
  MoreauJeanStepper stepper(*s.system, options);
  Trajectory t;
  const int nu = s.system->num_inputs();
  const auto result = stepper.simulate(
      s.q0, s.v0, [nu](double) { return Eigen::VectorXd::Zero(nu); }, s.duration,
      [&](const MoreauJeanState& state, const StepReport&) {
        Eigen::VectorXd x(state.q.size() + state.v.size());
        x << state.q, state.v;
        t.states.push_back(x);
      });
  t.ok = result.succeeded();
  t.message = result.message;
  t.worst_residual = result.summary.worst_residual;
  t.failures = result.summary.solver_failures;
  for (const auto& step : result.steps)
    t.unsupported = t.unsupported || step.solver_status == solvers::SolverStatus::kSingular;
  return t;
}

TEST(MoreauSolverAgreement, AllSolversGiveTheSameTrajectory) {
  for (const Scenario& s : scenarios()) {
    const Trajectory reference = run(s, "lemke");
    ASSERT_TRUE(reference.ok) << s.name << ": " << reference.message;
    ASSERT_EQ(reference.failures, 0) << s.name;
    for (const auto& info : solvers::friction_solvers()) {
      if (info.name == "lemke") continue;
      const auto start = std::chrono::steady_clock::now();
      const Trajectory t = run(s, info.name);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (t.unsupported) {
        std::printf("%s: %s cannot run it (status singular)\n", s.name.c_str(), info.name.c_str());
        continue;
      }
      ASSERT_TRUE(t.ok) << s.name << " " << info.name << ": " << t.message;
      ASSERT_EQ(t.states.size(), reference.states.size());
      double worst = 0.0;
      for (std::size_t k = 0; k < t.states.size(); ++k)
        worst = std::max(worst, (t.states[k] - reference.states[k]).lpNorm<Eigen::Infinity>());
      std::printf(
          "%s: %s vs lemke, max state difference %.3e (worst residual %.1e, %d steps "
          "above tolerance, %.2f s)\n",
          s.name.c_str(), info.name.c_str(), worst, t.worst_residual, t.failures, seconds);
      EXPECT_LT(worst, 1e-9 + t.worst_residual) << s.name << " " << info.name;
    }
  }
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
