// The ingredients of the jump gains, checked against central finite differences of the plain
// double functions: the mode flows' A = D_x f, B = D_u f (slip and stick with friction, both
// contacts closed), the guards' gradients (lift-off and stick→slip depend on u), the impact
// map's D_x g with another contact already closed, and the mode constraint rows. Then the
// input term of the jump gain (C.38) on a toy system whose guard depends on u and whose vector
// field and state jump at the event, where G_v ≠ 0: first-order prediction error O(ε²).
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <Eigen/LU>
#include <Eigen/QR>

#include <gtest/gtest.h>

#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/rk4.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::central_difference_jacobian;

double relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / std::max(1.0, b.lpNorm<Eigen::Infinity>());
}

class PlankBoxLinearisation : public ::testing::Test {
 protected:
  static model::PlankBoxParameters parameters() {
    model::PlankBoxParameters p;
    p.friction = 0.5;
    p.restitution = 0.0;
    return p;
  }
  PlankBoxLinearisation()
      : system_(parameters()), system_ad_(parameters()), model_(system_, system_ad_) {
    x_ << 0.45, 0.06, 0.05, -0.02, 0.3, -0.4, 1.2, 0.7;
    u_ << 0.3, -0.2, 0.05;
  }
  model::PlankBoxSystem<double> system_;
  model::PlankBoxSystem<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
  Eigen::VectorXd x_ = Eigen::VectorXd(8);
  Eigen::VectorXd u_ = Eigen::VectorXd(3);
};

using P = ContactPhase;

TEST_F(PlankBoxLinearisation, FlowJacobiansMatchFiniteDifferencesInEveryModeKind) {
  for (const HybridMode& mode :
       {HybridMode{P::kOpen, P::kOpen}, HybridMode{P::kSlipPositive, P::kOpen},
        HybridMode{P::kOpen, P::kStick}, HybridMode{P::kSlipNegative, P::kSlipPositive},
        HybridMode{P::kStick, P::kSlipNegative}}) {
    const FlowLinearisation lin = model_.linearise_flow(mode, x_, u_);
    EXPECT_LT((lin.f - model_.flow(mode, x_, u_)).norm(), 1e-12);
    const Eigen::MatrixXd A = central_difference_jacobian(
        [&](const Eigen::VectorXd& x) { return model_.flow(mode, x, u_); }, x_);
    const Eigen::MatrixXd B = central_difference_jacobian(
        [&](const Eigen::VectorXd& u) { return model_.flow(mode, x_, u); }, u_);
    EXPECT_LT(relative_difference(lin.A, A), 1e-7) << to_string(mode);
    EXPECT_LT(relative_difference(lin.B, B), 1e-7) << to_string(mode);
  }
}

TEST_F(PlankBoxLinearisation, ClosedContactsKeepZeroNormalAcceleration) {
  // c_1/c_2 (B.36–B.41): ζ̇_n = w_nᵀ v̇ + ẇ_nᵀ v = 0 on closed contacts, ζ̇_t = 0 when sticking,
  // and slip friction λ_t = −μ λ_n s.
  const HybridMode mode{P::kStick, P::kSlipPositive};
  const Eigen::VectorXd f = model_.flow(mode, x_, u_);
  const auto zeta_of = [&](const Eigen::VectorXd& x) {
    const Eigen::MatrixXd z = model_.relative_velocities(x);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(z.data(), z.size()));
  };
  const Eigen::VectorXd zeta_rate =
      central_difference_jacobian(zeta_of, x_) * f;  // d/dt along the flow
  EXPECT_NEAR(zeta_rate(0), 0.0, 1e-7);              // C_L normal
  EXPECT_NEAR(zeta_rate(1), 0.0, 1e-7);              // C_R normal
  EXPECT_NEAR(zeta_rate(2), 0.0, 1e-7);              // C_L tangential (stick)
  const ModeForces forces = model_.mode_forces(mode, x_, u_);
  EXPECT_NEAR(forces.lambda_t(1), -0.5 * forces.lambda_n(1), 1e-12);
}

TEST_F(PlankBoxLinearisation, GuardGradientsIncludeTheInputDependence) {
  const HybridMode mode{P::kStick, P::kOpen};
  for (const MicroEvent& event : {MicroEvent{0, GuardKind::kLiftOff, P::kOpen},
                                  MicroEvent{0, GuardKind::kStickToSlip, P::kSlipPositive},
                                  MicroEvent{0, GuardKind::kStickToSlip, P::kSlipNegative},
                                  MicroEvent{1, GuardKind::kImpact, P::kStick}}) {
    const GuardLinearisation lin = model_.linearise_guard(mode, event, x_, u_);
    EXPECT_NEAR(lin.value, model_.guard_value(mode, event, x_, u_), 1e-12);
    const auto gx = [&](const Eigen::VectorXd& x) {
      return Eigen::VectorXd::Constant(1, model_.guard_value(mode, event, x, u_));
    };
    const auto gu = [&](const Eigen::VectorXd& u) {
      return Eigen::VectorXd::Constant(1, model_.guard_value(mode, event, x_, u));
    };
    EXPECT_LT(relative_difference(lin.dx, central_difference_jacobian(gx, x_)), 1e-7)
        << to_string(event);
    EXPECT_LT(relative_difference(lin.du, central_difference_jacobian(gu, u_)), 1e-7)
        << to_string(event);
  }
  // Lift-off and stick→slip do depend on u (that is what makes the input term of C.38 matter).
  EXPECT_GT(model_.linearise_guard(mode, {0, GuardKind::kLiftOff, P::kOpen}, x_, u_).du.norm(),
            0.1);
}

TEST_F(PlankBoxLinearisation, ImpactMapJacobianWithAnotherContactClosed) {
  for (const MicroEvent& event : {MicroEvent{1, GuardKind::kImpact, P::kSlipPositive},
                                  MicroEvent{1, GuardKind::kImpact, P::kStick}}) {
    const HybridMode mode{P::kSlipNegative, P::kOpen};
    const ResetLinearisation lin = model_.linearise_reset(mode, event, x_);
    EXPECT_LT((lin.x_plus - model_.reset(mode, event, x_)).norm(), 1e-12);
    const Eigen::MatrixXd D = central_difference_jacobian(
        [&](const Eigen::VectorXd& x) { return model_.reset(mode, event, x); }, x_);
    EXPECT_LT(relative_difference(lin.dx, D), 1e-7) << to_string(event);
    // Inelastic: both normal velocities vanish after the impact; sticking also stops C_R's slip.
    const Eigen::MatrixXd zeta = model_.relative_velocities(lin.x_plus);
    EXPECT_NEAR(zeta(0, 0), 0.0, 1e-12);
    EXPECT_NEAR(zeta(1, 0), 0.0, 1e-12);
    if (event.phase_after == P::kStick) {
      EXPECT_NEAR(zeta(1, 1), 0.0, 1e-12);
    }
  }
  // A bounce (e > 0) cannot leave the contact closed.
  model::PlankBoxParameters bouncy = parameters();
  bouncy.restitution = 0.5;
  const model::PlankBoxSystem<double> s(bouncy);
  const model::PlankBoxSystem<AutoDiff> s_ad(bouncy);
  const MechanicalHybridModel m(s, s_ad);
  EXPECT_THROW(m.reset({P::kOpen, P::kOpen}, {0, GuardKind::kImpact, P::kStick}, x_),
               std::invalid_argument);
}

TEST_F(PlankBoxLinearisation, ModeConstraintRowsAreGapAndVelocityGradients) {
  const HybridMode mode{P::kStick, P::kOpen};
  const Eigen::MatrixXd C = model_.mode_constraint_rows(mode, x_);
  ASSERT_EQ(C.rows(), 3);
  const auto gap = [&](const Eigen::VectorXd& x) {
    return Eigen::VectorXd::Constant(1, model_.gaps(x)(0));
  };
  const auto zeta = [&](const Eigen::VectorXd& x) {
    return Eigen::VectorXd(model_.relative_velocities(x).row(0).transpose());
  };
  EXPECT_LT(relative_difference(C.row(0), central_difference_jacobian(gap, x_)), 1e-7);
  EXPECT_LT(relative_difference(C.middleRows(1, 2), central_difference_jacobian(zeta, x_)), 1e-7);
}

TEST_F(PlankBoxLinearisation, RejectsBadInput) {
  const HybridMode mode{P::kOpen, P::kOpen};
  EXPECT_THROW(model_.flow({P::kOpen}, x_, u_), std::invalid_argument);
  EXPECT_THROW(model_.flow(mode, Eigen::VectorXd::Zero(3), u_), std::invalid_argument);
  Eigen::VectorXd bad = x_;
  bad(2) = std::nan("");
  EXPECT_THROW(model_.flow(mode, bad, u_), std::invalid_argument);
  EXPECT_THROW(model_.linearise_guard(mode, {0, GuardKind::kLiftOff, P::kOpen}, x_, u_),
               std::invalid_argument);
}

// Both corners sticking on the plank: their tangent rows are equal (redundant constraints), so
// J M⁻¹ Jᵀ is singular. The accelerations must still be those of Gauss's principle, derived
// here independently by the null-space method: v̇ = v̇_p + N y with J v̇_p = −d (least-squares
// solution) and Nᵀ (M v̇ − F) = 0, N a basis of ker J.
TEST_F(PlankBoxLinearisation, RedundantStickingCornersFollowGaussPrinciple) {
  const model::PlankBoxParameters p = parameters();
  const double phi = -0.03, s = 0.55, omega = 0.7;
  const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d centre = s * e1 + 0.5 * (p.plank_thickness + p.box_height) * e2;
  Eigen::VectorXd x(8);  // box flat on the plank, turning rigidly with it about the hinge
  x << centre, phi, phi, -omega * centre.y(), omega * centre.x(), omega, omega;
  const Eigen::VectorXd q = x.head(4), v = x.tail(4);
  EXPECT_LT(model_.gaps(x).norm(), 1e-15);

  std::vector<model::Contact<double>> contacts;
  system_.find_contacts(q, v, 1e3, contacts);
  Eigen::MatrixXd J(4, 4);
  Eigen::VectorXd d(4);
  for (int i = 0; i < 2; ++i) {
    J.row(2 * i) = contacts[i].normal_direction(4).transpose();
    J.row(2 * i + 1) = contacts[i].tangent_directions(4).col(0).transpose();
    d(2 * i) = contacts[i].normal_drift;
    d(2 * i + 1) = contacts[i].tangent_drift(0);
  }
  EXPECT_LT((J.row(1) - J.row(3)).norm(), 1e-15);  // the redundancy
  const Eigen::MatrixXd M = Eigen::MatrixXd(system_.mass_matrix(q));
  const Eigen::VectorXd F = system_.input_matrix(q) * u_ - system_.bias_forces(q, v);
  const Eigen::MatrixXd N = Eigen::FullPivLU<Eigen::MatrixXd>(J).kernel();
  ASSERT_EQ(N.cols(), 1);  // the box turns with the plank
  const Eigen::VectorXd particular = J.completeOrthogonalDecomposition().solve(-d);
  const Eigen::VectorXd y =
      (N.transpose() * M * N).partialPivLu().solve(N.transpose() * (F - M * particular));
  const Eigen::VectorXd expected = particular + N * y;

  const Eigen::VectorXd f = model_.flow({P::kStick, P::kStick}, x, u_);
  EXPECT_LT((f.tail(4) - expected).lpNorm<Eigen::Infinity>(), 1e-10 * expected.norm())
      << f.tail(4).transpose() << "\n"
      << expected.transpose();
  EXPECT_LT((J * f.tail(4) + d).lpNorm<Eigen::Infinity>(), 1e-10);  // all four rows hold
  // The tangential forces split in proportion to the normal forces.
  const ModeForces forces = model_.mode_forces({P::kStick, P::kStick}, x, u_);
  EXPECT_NEAR(forces.lambda_t(0) / forces.lambda_n(0), forces.lambda_t(1) / forces.lambda_n(1),
              1e-10);
}

// --- Toy system with an input-dependent guard and a state jump --------------------------------
// x = (p, w). Mode "open": f = (w, u − p); mode "stick" (only a label here): f = (w, −2u − w/2).
// Guard γ = 1 − p − u/2 (crossed as p grows), reset g(p, w) = (p, −w/2 + p²/5).
class ToyModel final : public HybridModel {
 public:
  int state_size() const override { return 2; }
  int input_size() const override { return 1; }
  int num_contacts() const override { return 1; }
  Eigen::VectorXd flow(const HybridMode& mode, const Eigen::VectorXd& x,
                       const Eigen::VectorXd& u) const override {
    return mode[0] == P::kOpen ? Eigen::Vector2d(x(1), u(0) - x(0))
                               : Eigen::Vector2d(x(1), -2 * u(0) - 0.5 * x(1));
  }
  FlowLinearisation linearise_flow(const HybridMode& mode, const Eigen::VectorXd& x,
                                   const Eigen::VectorXd& u) const override {
    FlowLinearisation lin{flow(mode, x, u), Eigen::Matrix2d::Zero(), Eigen::Vector2d::Zero()};
    lin.A(0, 1) = 1;
    if (mode[0] == P::kOpen) {
      lin.A(1, 0) = -1;
      lin.B(1, 0) = 1;
    } else {
      lin.A(1, 1) = -0.5;
      lin.B(1, 0) = -2;
    }
    return lin;
  }
  GuardLinearisation linearise_guard(const HybridMode&, const MicroEvent&, const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& u) const override {
    return {1 - x(0) - 0.5 * u(0), Eigen::RowVector2d(-1, 0),
            Eigen::RowVectorXd::Constant(1, -0.5)};
  }
  ResetLinearisation linearise_reset(const HybridMode&, const MicroEvent&,
                                     const Eigen::VectorXd& x) const override {
    Eigen::Matrix2d D;
    D << 1, 0, 0.4 * x(0), -0.5;
    return {Eigen::Vector2d(x(0), -0.5 * x(1) + 0.2 * x(0) * x(0)), D};
  }
  Eigen::MatrixXd mode_constraint_rows(const HybridMode&, const Eigen::VectorXd&) const override {
    return Eigen::MatrixXd(0, 2);
  }
};

const MicroEvent kToyEvent{0, GuardKind::kImpact, P::kStick};

/// x(t) at `times` by RK4 (step ≤ 1e-3) with the event located by bisection on the step size.
std::vector<Eigen::VectorXd> simulate_toy(const ToyModel& model, Eigen::VectorXd x,
                                          const InputFunction& u, double t_end,
                                          const std::vector<double>& times, double* event_time) {
  HybridMode mode{P::kOpen};
  const auto step = [&](const Eigen::VectorXd& xs, double t, double h) {
    return test_support::rk4_step(
        [&](double ts, const Eigen::VectorXd& xt) {
          return Eigen::VectorXd(model.flow(mode, xt, u(ts)));
        },
        t, xs, h);
  };
  const auto guard = [&](const Eigen::VectorXd& xs, double t) {
    return model.linearise_guard(mode, kToyEvent, xs, u(t)).value;
  };
  std::vector<Eigen::VectorXd> out;
  std::size_t next = 0;
  double t = 0.0;
  while (t < t_end) {
    const double target = std::min({t + 1e-3, t_end, next < times.size() ? times[next] : t_end});
    Eigen::VectorXd x_end = step(x, t, target - t);
    if (mode[0] == P::kOpen && guard(x_end, target) < 0) {
      double lo = 0, hi = target - t;
      for (int i = 0; i < 200 && hi - lo > 1e-17; ++i) {
        const double mid = 0.5 * (lo + hi);
        (guard(step(x, t, mid), t + mid) < 0 ? hi : lo) = mid;
      }
      x = model.linearise_reset(mode, kToyEvent, step(x, t, hi)).x_plus;
      t += hi;
      *event_time = t;
      mode = {P::kStick};
      continue;
    }
    x = x_end;
    t = target;
    while (next < times.size() && times[next] <= t) {
      out.push_back(x);
      ++next;
    }
  }
  return out;
}

TEST(ToyInputDependentGuard, InputGainIsNonZeroAndPredictsToSecondOrder) {
  const ToyModel model;
  const InputFunction mu = [](double t) { return Eigen::VectorXd::Constant(1, 0.5 + 0.8 * t); };
  const InputFunction mu_rate = [](double) { return Eigen::VectorXd::Constant(1, 0.8); };
  const Eigen::Vector2d x0(0.0, 1.5);
  const double t_end = 1.5;
  double tau = 0.0;
  simulate_toy(model, x0, mu, t_end, {}, &tau);
  ASSERT_GT(tau, 0.1);
  std::vector<double> times;
  for (int i = 0; i <= 60; ++i)
    if (std::abs(t_end * i / 60 - tau) > 0.02) times.push_back(t_end * i / 60);
  double unused = 0.0;
  const auto nominal_states = simulate_toy(model, x0, mu, t_end, times, &unused);
  NominalTrajectory nominal{0.0, t_end,  x0, {P::kOpen}, {{tau, {kToyEvent}, std::nullopt}},
                            mu,  mu_rate};
  const TrajectorySensitivity sensitivity(model, nominal);
  const JumpGain& gain = sensitivity.events()[0].micro_event({0}).gain;
  EXPECT_GT(gain.Gv.norm(), 0.1);  // the input term of C.38 is exercised
  // Δ = −(D_xγ z + D_uγ v)/γ̇ with γ̇ = −w⁻ − μ̇/2.
  const Eigen::VectorXd x_minus = sensitivity.events()[0].x_minus();
  EXPECT_NEAR(gain.guard_rate, -x_minus(1) - 0.4, 1e-12);

  std::mt19937 rng(2);
  std::normal_distribution<double> normal;
  double lo = 1e9, hi = 0;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector2d z0(normal(rng), normal(rng));
    const double v0 = normal(rng), v1 = normal(rng);
    const InputFunction v = [=](double t) { return Eigen::VectorXd::Constant(1, v0 + v1 * t); };
    const auto z = sensitivity.perturbation(z0, v, times);
    std::vector<double> errors;
    for (const double eps : {1e-3, 5e-4, 1e-4, 5e-5, 1e-5, 5e-6}) {
      const InputFunction ue = [&](double t) { return Eigen::VectorXd(mu(t) + eps * v(t)); };
      const auto states = simulate_toy(model, x0 + eps * z0, ue, t_end, times, &unused);
      double worst = 0;
      for (std::size_t i = 0; i < times.size(); ++i)
        worst =
            std::max(worst, (states[i] - nominal_states[i] - eps * z[i]).lpNorm<Eigen::Infinity>());
      errors.push_back(worst);
    }
    for (int i = 0; i < 3; ++i) {
      const double r = errors[2 * i] / errors[2 * i + 1];
      EXPECT_GE(r, 3.0) << "direction " << k;
      EXPECT_LE(r, 5.0) << "direction " << k;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  std::cout << "[toy input-dependent guard] error ratios " << lo << " .. " << hi << "\n";
}

}  // namespace
}  // namespace impactbench::sensitivity
