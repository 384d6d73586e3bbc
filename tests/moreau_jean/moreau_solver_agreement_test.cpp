// Every registered friction solver gives the same Moreau–Jean trajectory as lemke (pivoting,
// exact up to round-off) on bouncing_ball, sliding_block and plank_box (all planar: the LCP
// conversion is exact there), one test case per scenario and solver. A solver that reports it
// cannot handle the problem at all (status singular) is a visible skip.
//
// The bound, in consistent units. Differences are measured in the kinetic-energy metric of the
// reference state: ‖δv‖_M = √(δvᵀ M δv) [√J] for velocities, ‖δq‖_M [√kg·m] for positions
// (planar coordinates: q̇ = v). One Moreau–Jean step maps the free velocity v_f to the
// post-step one by an impulse that projects in the M-metric, which does not expand
// M-distances, so per-step solver errors add up. For an active contact the FCLIB residual ρ
// (relative to ‖q‖, q = Hᵀ v_f) gives W δr ≈ ρ‖q‖, so ‖δv‖_M = √(δrᵀ W δr) ≤ ρ ‖q‖ / √W and,
// by Cauchy–Schwarz in the M-metric, ‖q‖ ≤ √W ‖v_f‖_M: ‖δv‖_M ≤ ρ ‖v_f‖_M. The De Saxcé term
// μ‖u_t‖ of the residual makes that map (1 + μ)-Lipschitz. With ‖v_f‖_M taken as the larger of
// the step's end velocities, after N steps
//   ‖δv_N‖_M ≤ Σ_k (1 + μ) ρ_k max(‖v_k‖_M, ‖v_{k+1}‖_M),     ‖δq_N‖_M ≤ h Σ_k ‖δv_k‖_M,
// accumulated from the solver's own per-step residuals, each at least the tolerance 1e-12 that
// both runs are asked for (lemke's round-off is below it).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

struct Scenario {
  std::string name;
  std::unique_ptr<model::LagrangianSystem<double>> system;
  Eigen::VectorXd q0, v0;
  double duration = 0.0;
  ForceTreatment forces = ForceTreatment::kExplicit;
  double friction = 0.0;  ///< μ of every contact
};

std::vector<Scenario> scenarios() {
  std::vector<Scenario> list;
  {
    test_support::PlanarWorldSpec spec;
    spec.bodies = {test_support::disk("ball", 0.1, 1.0)};
    spec.material = {0.0, 0.9};
    list.push_back({"bouncing_ball",
                    test_support::make_planar_world(test_support::PlanarKind::kProjectSystem, spec),
                    Eigen::Vector3d(0, 1, 0), Eigen::Vector3d::Zero(), 2.0});
  }
  {
    test_support::PlanarWorldSpec spec;
    spec.bodies = {test_support::box("block", 0.2, 0.2, 1.0)};
    spec.material = {0.5, 0.0};
    list.push_back({"sliding_block",
                    test_support::make_planar_world(test_support::PlanarKind::kProjectSystem, spec),
                    Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(2, 0, 0), 0.6});
    list.back().friction = spec.material.friction;
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
    list.back().friction = p.friction;
  }
  return list;
}

struct Trajectory {
  std::vector<Eigen::VectorXd> q, v;  ///< at t_0 and after every step
  std::vector<double> residuals;      ///< per step (0 without active contacts)
  bool ok = false;
  bool unsupported = false;  ///< some step reported kSingular
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
  options.record_steps = true;
  options.on_failure = OnFailure::kWarn;
  MoreauJeanStepper stepper(*s.system, options);
  Trajectory t;
  const int nu = s.system->num_inputs();
  const auto result = stepper.simulate(
      s.q0, s.v0, [nu](double) { return Eigen::VectorXd::Zero(nu); }, s.duration,
      [&](const MoreauJeanState& state, const StepReport&) {
        t.q.push_back(state.q);
        t.v.push_back(state.v);
      });
  t.ok = result.succeeded();
  t.message = result.message;
  t.failures = result.summary.solver_failures;
  for (const auto& step : result.steps) {
    t.residuals.push_back(step.residual);
    t.unsupported = t.unsupported || step.solver_status == solvers::SolverStatus::kSingular;
  }
  return t;
}

double m_norm(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
              const Eigen::VectorXd& x) {
  return std::sqrt(x.dot(system.mass_matrix(q) * x));
}

struct Case {
  std::string scenario;
  std::string solver;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const char* scenario : {"bouncing_ball", "sliding_block", "plank_box"})
    for (const auto& info : solvers::friction_solvers())
      if (info.name != "lemke") out.push_back({scenario, info.name});
  return out;
}

Scenario scenario_named(const std::string& name) {
  for (Scenario& s : scenarios())
    if (s.name == name) return std::move(s);
  throw std::invalid_argument("no scenario " + name);
}

class MoreauSolverAgreement : public ::testing::TestWithParam<Case> {};

TEST_P(MoreauSolverAgreement, SameTrajectoryAsLemkeWithinTheResidualBound) {
  const Case& c = GetParam();
  const Scenario s = scenario_named(c.scenario);
  const Trajectory reference = run(s, "lemke");
  ASSERT_TRUE(reference.ok) << reference.message;
  ASSERT_EQ(reference.failures, 0);
  const Trajectory t = run(s, c.solver);
  if (t.unsupported) GTEST_SKIP() << c.solver << " reports the problem singular (cannot run it)";
  ASSERT_TRUE(t.ok) << t.message;
  ASSERT_EQ(t.q.size(), reference.q.size());
  const double h = s.duration / static_cast<double>(t.residuals.size());
  double bound_v = 0.0, bound_q = 0.0, worst_v_ratio = 0.0, worst_q_ratio = 0.0;
  double worst_v = 0.0, worst_q = 0.0;
  for (std::size_t k = 1; k < t.q.size(); ++k) {
    const Eigen::VectorXd& q_ref = reference.q[k];
    const double residual = std::max(t.residuals[k - 1], 1e-12);
    bound_v += (1.0 + s.friction) * residual *
               std::max(m_norm(*s.system, reference.q[k - 1], reference.v[k - 1]),
                        m_norm(*s.system, q_ref, reference.v[k]));
    bound_q += h * bound_v;
    const double dv = m_norm(*s.system, q_ref, t.v[k] - reference.v[k]);
    const double dq = m_norm(*s.system, q_ref, t.q[k] - q_ref);
    worst_v = std::max(worst_v, dv);
    worst_q = std::max(worst_q, dq);
    worst_v_ratio = std::max(worst_v_ratio, dv / bound_v);
    worst_q_ratio = std::max(worst_q_ratio, dq / std::max(bound_q, 1e-300));
  }
  std::printf(
      "%s %s: max |dv|_M %.3e sqrt(J), |dq|_M %.3e; bound ratios v %.3g q %.3g "
      "(%d steps above tolerance)\n",
      c.scenario.c_str(), c.solver.c_str(), worst_v, worst_q, worst_v_ratio, worst_q_ratio,
      t.failures);
  EXPECT_LE(worst_v_ratio, 1.0);
  EXPECT_LE(worst_q_ratio, 1.0);
  // The bound holds whatever residual a step reaches; reaching the tolerance is required too,
  // but for a few steps: iterative solvers stall near 1e-6 on a handful of steps of the
  // plank–box's near-redundant two-corner contact (with on_failure = warn, counted here).
  EXPECT_LE(t.failures, static_cast<int>(t.residuals.size()) / 100);
}

INSTANTIATE_TEST_SUITE_P(EverySolver, MoreauSolverAgreement, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& test) {
                           std::string name = test.param.scenario + "_" + test.param.solver;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace impactbench::engines::moreau_jean
