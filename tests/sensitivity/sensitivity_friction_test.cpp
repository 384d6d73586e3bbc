// Sensitivity through friction-mode changes on the scenarios' own systems, planar boxes on a
// line as lib/engines/system_builder builds them from scenarios/sliding_block.toml (slip → stick
// of both bottom corners, guard ζ_t = 0) and scenarios/incline.toml (stick → slip caused by the
// push u = c t, guard μλ_n + s λ_t = 0, which depends on the input). Two sticking corners give
// redundant constraint rows (equal tangent rows), which the model resolves with least-norm
// multipliers split in proportion to the normal forces; both corners then switch together.
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/engines/scenario_hybrid_model.hpp"
#include "tests/support/lib/hybrid_reference_simulator.hpp"
#include "tests/support/lib/sensitivity_convergence.hpp"

namespace impactbench::sensitivity {
namespace {

/// A box scenario: model, initial mode (bottom corners closed in `closed`), nominal run with
/// probes around its events, and the sensitivity along it.
class BoxCase {
 public:
  BoxCase(const std::string& name, ContactPhase closed, double t_end) : scenario_(name) {
    const MechanicalHybridModel& model = scenario_.model();
    setup_.model = &model;
    setup_.mode0 = scenario_.initial_mode(closed);
    setup_.x0 = scenario_.x0();
    setup_.input = scenario_.input();
    setup_.input_rate = scenario_.input_rate();
    setup_.t_end = t_end;
    setup_.options.impact_phase = HybridMode(setup_.mode0.size(), ContactPhase::kStick);
    // Every mode's motion is a polynomial of degree ≤ 3 in t (constant or linearly growing
    // force, no rotation), which RK4 integrates exactly: large steps only reduce round-off.
    setup_.options.max_step = 0.05;
    nominal_run_ = test_support::nominal_run_with_event_probes(setup_, 61);
    sensitivity_ = std::make_unique<TrajectorySensitivity>(
        model, test_support::nominal_of(setup_, nominal_run_), SensitivityOptions{0.05});
  }

  double parameter(const std::string& name) const { return scenario_.scenario().parameter(name); }
  double analytic(const std::string& name) const { return scenario_.scenario().analytic(name); }
  const MechanicalHybridModel& model() const { return scenario_.model(); }
  const test_support::ConvergenceSetup& setup() const { return setup_; }
  const test_support::ReferenceRun& nominal_run() const { return nominal_run_; }
  const TrajectorySensitivity& sensitivity() const { return *sensitivity_; }
  std::vector<int> closed_contacts() const {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(setup_.mode0.size()); ++i)
      if (is_closed(setup_.mode0[i])) out.push_back(i);
    return out;
  }

  /// The acceptance check: 20 random directions (state and input), ε = 1e-3 … 1e-5.
  void expect_second_order(const std::string& label, unsigned seed) const {
    std::mt19937 rng(seed);
    std::vector<test_support::PerturbationDirection> directions;
    for (int k = 0; k < 20; ++k) directions.push_back(test_support::random_direction(setup_, rng));
    test_support::expect_second_order(setup_, nominal_run_, *sensitivity_, directions, label);
  }

 private:
  test_support::ScenarioHybridModel scenario_;
  test_support::ConvergenceSetup setup_;
  test_support::ReferenceRun nominal_run_;
  std::unique_ptr<TrajectorySensitivity> sensitivity_;
};

// --- sliding_block: square box launched with v0 = 2 m/s on flat ground, μ = 0.5 ------------

/// One case per test suite (building it runs the nominal and linearises it).
template <typename Tag>
class SharedBoxCase : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { shared_ = Tag::make(); }
  static void TearDownTestSuite() { shared_.reset(); }
  static inline std::unique_ptr<BoxCase> shared_;
  const BoxCase& case_ = *shared_;
};

struct SlidingBlockTag {
  static std::unique_ptr<BoxCase> make() {
    return std::make_unique<BoxCase>("sliding_block", ContactPhase::kSlipPositive, 0.6);
  }
};
using SlidingBlockSensitivity = SharedBoxCase<SlidingBlockTag>;

// Two slipping corners: the friction −μ Σλ_n with Σλ_n = m g decelerates the box at μ g, the
// box neither rotates nor lifts, whatever the split of λ_n between the corners.
TEST_F(SlidingBlockSensitivity, SlipsWithTheAnalyticDeceleration) {
  ASSERT_EQ(case_.closed_contacts().size(), 2u);
  const double m = case_.parameter("mass"), g = case_.parameter("g");
  const ModeForces forces =
      case_.model().mode_forces(case_.setup().mode0, case_.setup().x0, Eigen::VectorXd());
  EXPECT_NEAR(forces.v_dot(0), -case_.analytic("deceleration"), 1e-12);
  EXPECT_NEAR(forces.v_dot(1), 0.0, 1e-12);
  EXPECT_NEAR(forces.v_dot(2), 0.0, 1e-12);
  EXPECT_NEAR(forces.lambda_n.sum(), m * g, 1e-12);
  EXPECT_NEAR(std::abs(forces.lambda_t.sum()), case_.parameter("friction") * m * g, 1e-12);
}

// Both corners stop at v0/(μg) after v0²/(2μg); at rest the stick mode is redundant (equal
// tangent rows) and carries the weight with no friction.
TEST_F(SlidingBlockSensitivity, BothCornersStickAtTheAnalyticStopTime) {
  const auto& run = case_.nominal_run();
  ASSERT_EQ(run.events.size(), 2u);
  for (const auto& e : run.events) {
    EXPECT_EQ(e.event.kind, GuardKind::kSlipToStick);
    EXPECT_NEAR(e.time, case_.analytic("stop_time"), 1e-12);
  }
  EXPECT_NE(run.events[0].event.contact, run.events[1].event.contact);
  EXPECT_NEAR(run.final_state(0) - case_.setup().x0(0), case_.analytic("stop_distance"), 1e-12);
  EXPECT_LT(run.final_state.tail(3).norm(), 1e-12);
  const ModeForces rest = case_.model().mode_forces(run.final_mode, run.final_state, {});
  EXPECT_LT(rest.v_dot.norm(), 1e-12);
  EXPECT_LT(rest.lambda_t.norm(), 1e-12);
  EXPECT_NEAR(rest.lambda_n.sum(), case_.parameter("mass") * case_.parameter("g"), 1e-12);
  // One macro event whose two guards coincide: they switch together (joined) in either order.
  const ConewiseJumpGain& stop = case_.sensitivity().events().at(0);
  ASSERT_EQ(stop.events().size(), 2u);
  EXPECT_TRUE(stop.micro_event({0, 1}).joined);
  EXPECT_EQ(stop.all_gains().size(), 2u);
  EXPECT_LT(stop.order_dependence(), 1e-15);
}

// Stop distance v0²/(2μg): ∂x_end/∂x0 = 1, ∂x_end/∂v0 = v0/(μg), and the box is at rest.
TEST_F(SlidingBlockSensitivity, EndPointMatrixMatchesTheClosedForm) {
  const InputBasis none = [](double) { return Eigen::MatrixXd(0, 0); };
  const EndPointSensitivity end = case_.sensitivity().end_point_sensitivity(none);
  EXPECT_NEAR(end.state(0, 0), 1.0, 1e-10);
  EXPECT_NEAR(end.state(0, 3), case_.parameter("v0") / case_.analytic("deceleration"), 1e-10);
  // Perturbations that keep both corners on the ground: shifts of x and vx. (Off that set, e.g.
  // a tilt, the slip mode's flow does not apply and the matrix entries carry no meaning.)
  const auto& setup = case_.setup();
  const Eigen::MatrixXd tangent =
      Eigen::FullPivLU<Eigen::MatrixXd>(case_.model().mode_constraint_rows(setup.mode0, setup.x0))
          .kernel();
  ASSERT_EQ(tangent.cols(), 2);
  EXPECT_LT((end.state * tangent).bottomRows(3).norm(), 1e-10);  // at rest whatever x0, v0
  // Saltation of slip → stick: the velocity perturbation is absorbed (G_z row vx = 0).
  const ComposedGain gain = case_.sensitivity().events()[0].gain_of_order({0, 1});
  EXPECT_LT((gain.Gz * tangent).row(3).norm(), 1e-12);
}

TEST_F(SlidingBlockSensitivity, PredictionErrorShrinksLikeEpsilonSquared) {
  case_.expect_second_order("sliding_block", 21);
}

// --- incline: α = 20°, μ = 0.5, push u = c t down the slope ---------------------------------

struct InclineTag {
  static std::unique_ptr<BoxCase> make() {
    return std::make_unique<BoxCase>("incline", ContactPhase::kStick, 2.0);
  }
};
class InclineSensitivity : public SharedBoxCase<InclineTag> {
 protected:
  /// The unit vector down the slope.
  Eigen::Vector2d down_slope() const {
    const double alpha = case_.parameter("angle") * M_PI / 180.0;
    return {-std::cos(alpha), -std::sin(alpha)};
  }
};

// Sticking with redundant rows: the box is held (v̇ = 0), Σλ_n = m g cos α, |Σλ_t| = m g sin α +
// c t, and the tangential split follows the (unequal) normal forces.
TEST_F(InclineSensitivity, StickForcesSplitInProportionToTheNormalForces) {
  const std::vector<int> closed = case_.closed_contacts();
  ASSERT_EQ(closed.size(), 2u);
  const double m = case_.parameter("mass"), g = case_.parameter("g");
  const double alpha = case_.parameter("angle") * M_PI / 180.0, c = case_.parameter("push_rate");
  const double t = 0.6;
  const ModeForces f =
      case_.model().mode_forces(case_.setup().mode0, case_.setup().x0, case_.setup().input(t));
  EXPECT_LT(f.v_dot.norm(), 1e-12);
  const int a = closed[0], b = closed[1];
  EXPECT_NEAR(f.lambda_n(a) + f.lambda_n(b), m * g * std::cos(alpha), 1e-12);
  EXPECT_NEAR(std::abs(f.lambda_t(a) + f.lambda_t(b)), m * g * std::sin(alpha) + c * t, 1e-12);
  EXPECT_GT(std::abs(f.lambda_n(a) - f.lambda_n(b)), 1e-2);
  EXPECT_NEAR(f.lambda_t(a) / f.lambda_n(a), f.lambda_t(b) / f.lambda_n(b), 1e-12);
}

// Both corners slip at m g (μ cos α − sin α)/c; afterwards the box slides down the slope as the
// scenario's closed form (c (T − t_s)³/(6m) and c (T − t_s)²/(2m) when the push causes the slip).
TEST_F(InclineSensitivity, SlipsAtTheAnalyticTimeAndSlidesAsTheClosedForm) {
  const auto& run = case_.nominal_run();
  ASSERT_EQ(run.events.size(), 2u);
  for (const auto& e : run.events) {
    EXPECT_EQ(e.event.kind, GuardKind::kStickToSlip);
    EXPECT_NEAR(e.time, case_.analytic("slip_time"), 1e-12);
  }
  EXPECT_EQ(run.events[0].event.phase_after, run.events[1].event.phase_after);
  const Eigen::Vector2d d = down_slope();
  EXPECT_NEAR(d.dot(run.final_state.head(2) - case_.setup().x0.head(2)),
              case_.analytic("slip_distance"), 1e-10);
  EXPECT_NEAR(d.dot(run.final_state.segment(3, 2)), case_.analytic("slip_speed"), 1e-10);
  EXPECT_NEAR(run.final_state(2), case_.setup().x0(2), 1e-12);  // no tipping
}

// The guard depends on the input: Δ = −(D_uγ v)/γ̇ = −v/c (the slip comes earlier by v/c for a
// push offset v); the state and field are continuous across the switch, so G_z = I, G_v = 0.
TEST_F(InclineSensitivity, InputDependentGuardShiftsTheSlipTimeButNotTheState) {
  const double c = case_.parameter("push_rate");
  const ConewiseJumpGain& event = case_.sensitivity().events().at(0);
  ASSERT_EQ(event.events().size(), 2u);
  EXPECT_TRUE(event.micro_event({0, 1}).joined);
  const JumpGain& gain = event.micro_event({0}).gain;
  EXPECT_NEAR(gain.b(0), -1.0 / c, 1e-9);
  const ComposedGain composed = event.gain_of_order({0, 1});
  EXPECT_LT((composed.Gz - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-9);
  EXPECT_LT(composed.Gv.norm(), 1e-9);
  // First-order slip-time shift against a perturbed simulation with u + ε v0.
  const double eps = 1e-6, v0 = 0.7;
  const auto& setup = case_.setup();
  const auto perturbed = test_support::simulate_reference(
      case_.model(), setup.mode0, setup.x0,
      [&](double t) { return Eigen::VectorXd(setup.input(t).array() + eps * v0); }, 0.0,
      setup.t_end, {}, setup.options);
  ASSERT_EQ(perturbed.events.size(), 2u);
  const double shift = (perturbed.events[0].time - case_.nominal_run().events[0].time) / eps;
  EXPECT_NEAR(shift, gain.b(0) * v0, 1e-5);
}

// After the slip, s̈ = (c (t − t_s) + v(t))/m along the slope to first order (the perturbed slip
// time enters at second order because the net force vanishes at t_s), so
// z_s(T) = ∫_{t_s}^T (T − r) v(r) dr / m and ż_s(T) = ∫_{t_s}^T v(r) dr / m.
TEST_F(InclineSensitivity, EndPointInputMatrixMatchesTheClosedForm) {
  const InputBasis affine = [](double t) {
    Eigen::MatrixXd V(1, 2);
    V << 1.0, t;
    return V;
  };
  const EndPointSensitivity end = case_.sensitivity().end_point_sensitivity(affine);
  const double m = case_.parameter("mass");
  const double ts = case_.analytic("slip_time"), T = case_.setup().t_end, d = T - ts;
  const Eigen::Vector2d s = down_slope();
  EXPECT_NEAR(s.dot(end.input.col(0).head(2)), d * d / (2 * m), 1e-9);
  EXPECT_NEAR(s.dot(end.input.col(1).head(2)), (ts * d * d / 2 + d * d * d / 6) / m, 1e-9);
  EXPECT_NEAR(s.dot(end.input.col(0).segment(3, 2)), d / m, 1e-9);
  EXPECT_NEAR(end.input.row(2).norm(), 0.0, 1e-9);
  // The only admissible state perturbation, a shift along the slope, is carried unchanged.
  const Eigen::VectorXd shift = (Eigen::VectorXd(6) << s, 0.0, 0.0, 0.0, 0.0).finished();
  EXPECT_LT((end.state * shift - shift).norm(), 1e-10);
}

TEST_F(InclineSensitivity, PredictionErrorShrinksLikeEpsilonSquared) {
  case_.expect_second_order("incline", 33);
}

}  // namespace
}  // namespace impactbench::sensitivity
