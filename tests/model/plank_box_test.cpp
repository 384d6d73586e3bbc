// Checks of the plank–box model against independent geometry, finite differences, the
// Lagrangian (energy function) and conservation laws; see the derivation in the header.
#include "lib/model/plank_box/plank_box_system.hpp"

#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/rk4.hpp"

namespace impactbench::model {
namespace {

using System = PlankBoxSystem<double>;
using AutoDiffSystem = PlankBoxSystem<AutoDiff>;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using test_support::integrate_rk4;

constexpr double kFdStep = 1e-5;       // central differences: truncation ~1e-10
constexpr double kFdTolerance = 1e-6;  // relative, as the acceptance criterion asks
// Nested (second) differences: velocity steps may be large because T is quadratic in v (the
// difference is then exact up to round-off ~1e-16 E / h²); position steps balance truncation
// h² against round-off.
constexpr double kVelocityStep2 = 1e-3;
constexpr double kPositionStep2 = 1e-4;
constexpr double kRelativeFloor = 1e-2;  // denominators below this count as absolute errors

double relative_error(const VectorXd& actual, const VectorXd& expected) {
  return (actual - expected).norm() / std::max(expected.norm(), kRelativeFloor);
}
double relative_error(double actual, double expected) {
  return std::abs(actual - expected) / std::max(std::abs(expected), kRelativeFloor);
}

struct State {
  VectorXd q;
  VectorXd v;
};

// Box centre anywhere over the plank, angles within ±1 rad, velocities within ±2.
State random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> along(0.0, 1.0), above(-0.2, 0.5), angle(-1.0, 1.0),
      rate(-2.0, 2.0);
  State s{VectorXd(4), VectorXd(4)};
  s.q << along(rng), above(rng), angle(rng), angle(rng);
  s.v << rate(rng), rate(rng), rate(rng), rate(rng);
  return s;
}

// Independent geometry: the corner in the world by rotating its body-frame offset, then its
// coordinates in the plank frame (hinge at the origin, axis along φ).
Eigen::Vector2d corner_in_plank_frame(const PlankBoxParameters& p, const VectorXd& q,
                                      PlankBoxCorner corner) {
  const double side = corner == PlankBoxCorner::kLeft ? -1.0 : 1.0;
  const Eigen::Vector2d body(side * p.box_length / 2, -p.box_height / 2);
  const Eigen::Vector2d world = q.head<2>() + Eigen::Rotation2Dd(q(2)) * body;
  return Eigen::Rotation2Dd(-q(3)) * world;
}

double reference_gap(const PlankBoxParameters& p, const VectorXd& q, PlankBoxCorner corner) {
  return corner_in_plank_frame(p, q, corner).y() - p.plank_thickness / 2;
}
double reference_tangential_coordinate(const PlankBoxParameters& p, const VectorXd& q,
                                       PlankBoxCorner corner) {
  return corner_in_plank_frame(p, q, corner).x();
}

template <typename Function>
VectorXd central_gradient(const Function& f, const VectorXd& x, double step = kFdStep) {
  return test_support::central_difference_gradient(f, x, step);
}

template <typename Function>
MatrixXd central_jacobian(const Function& f, const VectorXd& x, double step = kFdStep) {
  return test_support::central_difference_jacobian(f, x, step);
}

// d/dt of g(q + t v) at t = 0, by central differences.
template <typename Function>
auto derivative_along(const Function& g, const VectorXd& q, const VectorXd& v) {
  return test_support::central_difference_along(g, q, v, kFdStep);
}

// ẋ = f(x, u) with x = (q, v): the smooth, contact-free flow M v̇ = S u − H.
template <typename Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, 1> flow(const PlankBoxSystem<Scalar>& system,
                                              const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& x,
                                              const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& u) {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const Vector q = x.head(4), v = x.tail(4);
  const Matrix M(system.mass_matrix(q));
  const Vector rhs = system.input_matrix(q) * u - system.bias_forces(q, v);
  Vector xdot(8);
  xdot << system.position_rate(q, v), M.partialPivLu().solve(rhs);
  return xdot;
}

// ---------------------------------------------------------------------------------------------
// Parameters

TEST(PlankBoxParameters, DefaultInertias) {
  const PlankBoxParameters p;
  EXPECT_NO_THROW(p.validate());
  EXPECT_DOUBLE_EQ(p.box_inertia(), 1.0 * (0.2 * 0.2 + 0.1 * 0.1) / 12);
  EXPECT_DOUBLE_EQ(p.plank_centre_inertia(), 2.0 * (1.0 + 0.02 * 0.02) / 12);
  EXPECT_DOUBLE_EQ(p.plank_hinge_inertia(), 2.0 / 4 + 2.0 * (1.0 + 0.02 * 0.02) / 12);
  PlankBoxParameters given;
  given.plank_inertia = 0.3;
  EXPECT_DOUBLE_EQ(given.plank_hinge_inertia(), 0.5 + 0.3);
}

TEST(PlankBoxParameters, InvalidValuesRejectedNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* field;
    void (*spoil)(PlankBoxParameters&, double);
    double value;
  };
  const Case cases[] = {
      {"box_mass", [](PlankBoxParameters& p, double x) { p.box_mass = x; }, 0.0},
      {"box_mass", [](PlankBoxParameters& p, double x) { p.box_mass = x; }, -1.0},
      {"box_mass", [](PlankBoxParameters& p, double x) { p.box_mass = x; }, nan},
      {"plank_mass", [](PlankBoxParameters& p, double x) { p.plank_mass = x; }, -2.0},
      {"plank_mass", [](PlankBoxParameters& p, double x) { p.plank_mass = x; }, nan},
      {"box_length", [](PlankBoxParameters& p, double x) { p.box_length = x; }, nan},
      {"box_height", [](PlankBoxParameters& p, double x) { p.box_height = x; }, 0.0},
      {"plank_length", [](PlankBoxParameters& p, double x) { p.plank_length = x; }, -1.0},
      {"plank_thickness", [](PlankBoxParameters& p, double x) { p.plank_thickness = x; }, 0.0},
      {"plank_inertia", [](PlankBoxParameters& p, double x) { p.plank_inertia = x; }, -0.1},
      {"plank_stiffness", [](PlankBoxParameters& p, double x) { p.plank_stiffness = x; }, -1.0},
      {"plank_damping", [](PlankBoxParameters& p, double x) { p.plank_damping = x; }, nan},
      {"gravity", [](PlankBoxParameters& p, double x) { p.gravity = x; }, INFINITY},
      {"friction", [](PlankBoxParameters& p, double x) { p.friction = x; }, -0.1},
      {"friction", [](PlankBoxParameters& p, double x) { p.friction = x; }, nan},
      {"restitution", [](PlankBoxParameters& p, double x) { p.restitution = x; }, 1.5},
      {"restitution", [](PlankBoxParameters& p, double x) { p.restitution = x; }, -0.1},
      {"restitution", [](PlankBoxParameters& p, double x) { p.restitution = x; }, nan},
  };
  for (const Case& c : cases) {
    PlankBoxParameters p;
    c.spoil(p, c.value);
    try {
      System system(p);
      ADD_FAILURE() << c.field << " = " << c.value << " was accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(c.field), std::string::npos)
          << "message '" << error.what() << "' does not name " << c.field;
    }
  }
  // The boundary values are valid.
  PlankBoxParameters edge;
  edge.friction = 0.0;
  edge.restitution = 1.0;
  edge.plank_stiffness = 0.0;
  edge.plank_damping = 0.0;
  EXPECT_NO_THROW(System{edge});
}

TEST(PlankBoxSystem, WrongStateSizesRejected) {
  const System system;
  EXPECT_THROW(system.bias_forces(VectorXd::Zero(3), VectorXd::Zero(4)), std::invalid_argument);
  EXPECT_THROW(system.energy(VectorXd::Zero(4), VectorXd::Zero(5)), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// The reference integrator itself: global error O(h⁴) on ẍ = −x.

TEST(Rk4, FourthOrderOnHarmonicOscillator) {
  const test_support::StateDerivative oscillator = [](double, const VectorXd& x) {
    VectorXd d(2);
    d << x(1), -x(0);
    return d;
  };
  const VectorXd x0 = (VectorXd(2) << 1.0, 0.0).finished();
  auto error = [&](int steps) {
    const VectorXd x = integrate_rk4(oscillator, 0.0, x0, 2.0, steps);
    return std::hypot(x(0) - std::cos(2.0), x(1) + std::sin(2.0));
  };
  const double ratio = error(50) / error(100);
  EXPECT_NEAR(ratio, 16.0, 0.5);  // 2⁴
}

// ---------------------------------------------------------------------------------------------
// Contacts

TEST(PlankBoxContacts, GapsAndJacobiansMatchGeometryAndFiniteDifferences) {
  const System system;
  const PlankBoxParameters& p = system.parameters();
  std::mt19937 rng(20261121);
  double worst_gap = 0, worst_wn = 0, worst_wt = 0, worst_zeta_t = 0, worst_wn_dot = 0,
         worst_wt_dot = 0;
  for (int sample = 0; sample < 100; ++sample) {
    const State s = random_state(rng);
    for (const PlankBoxCorner corner : {PlankBoxCorner::kLeft, PlankBoxCorner::kRight}) {
      const Contact<double> c = system.corner_contact(s.q, s.v, corner);
      const auto gap = [&](const VectorXd& q) { return system.corner_contact(q, s.v, corner).gap; };
      const auto w_n = [&](const VectorXd& q) {
        return system.corner_contact(q, s.v, corner).normal_direction(4);
      };
      const auto w_t = [&](const VectorXd& q) {
        return VectorXd(system.corner_contact(q, s.v, corner).tangent_directions(4).col(0));
      };
      const auto tangential = [&](const VectorXd& q) {
        return reference_tangential_coordinate(p, q, corner);
      };

      worst_gap = std::max(worst_gap, std::abs(c.gap - reference_gap(p, s.q, corner)));
      worst_wn =
          std::max(worst_wn, relative_error(c.normal_direction(4), central_gradient(gap, s.q)));
      worst_wt = std::max(worst_wt, relative_error(w_t(s.q), central_gradient(tangential, s.q)));

      // ζ_t is the corner's velocity relative to the coincident plank point, along the plank.
      const auto corner_world = [&](const VectorXd& q) {
        const double side = corner == PlankBoxCorner::kLeft ? -1.0 : 1.0;
        return Eigen::Vector2d(q.head<2>() +
                               Eigen::Rotation2Dd(q(2)) *
                                   Eigen::Vector2d(side * p.box_length / 2, -p.box_height / 2));
      };
      const Eigen::Vector2d point = corner_world(s.q);
      const Eigen::Vector2d corner_velocity = derivative_along(corner_world, s.q, s.v);
      const Eigen::Vector2d plank_point_velocity = s.v(3) * Eigen::Vector2d(-point.y(), point.x());
      const Eigen::Vector2d along_plank(std::cos(s.q(3)), std::sin(s.q(3)));
      const double zeta_t = along_plank.dot(corner_velocity - plank_point_velocity);
      worst_zeta_t = std::max(worst_zeta_t, relative_error(c.relative_velocity(s.v)(1), zeta_t));

      worst_wn_dot = std::max(
          worst_wn_dot, relative_error(c.normal_drift, derivative_along(w_n, s.q, s.v).dot(s.v)));
      worst_wt_dot =
          std::max(worst_wt_dot,
                   relative_error(c.tangent_drift(0), derivative_along(w_t, s.q, s.v).dot(s.v)));
    }
  }
  std::cout << "max |gap - geometry| " << worst_gap << "; max relative FD error: w_n " << worst_wn
            << ", W_t " << worst_wt << ", zeta_t " << worst_zeta_t << ", w_n_dot'v " << worst_wn_dot
            << ", W_t_dot'v " << worst_wt_dot << "\n";
  EXPECT_LT(worst_gap, 1e-14);
  EXPECT_LT(worst_wn, kFdTolerance);
  EXPECT_LT(worst_wt, kFdTolerance);
  EXPECT_LT(worst_zeta_t, kFdTolerance);
  EXPECT_LT(worst_wn_dot, kFdTolerance);
  EXPECT_LT(worst_wt_dot, kFdTolerance);
}

TEST(PlankBoxContacts, GapsEqualWhenBoxIsAlignedWithPlank) {
  const System system;
  const PlankBoxParameters& p = system.parameters();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> along(0.1, 0.9), above(0.0, 0.3), angle(-0.5, 0.5);
  std::vector<Contact<double>> contacts;
  for (int sample = 0; sample < 20; ++sample) {
    VectorXd q(4);
    q << along(rng), above(rng), 0.0, 0.0;
    system.find_contacts(q, VectorXd::Zero(4), 0.0, contacts);
    ASSERT_EQ(contacts.size(), 2u);
    EXPECT_DOUBLE_EQ(contacts[0].gap, contacts[1].gap);
    EXPECT_NEAR(contacts[0].gap, q(1) - p.box_height / 2 - p.plank_thickness / 2, 1e-15);
    // Rotating plank and box together keeps the gaps equal.
    const double phi = angle(rng);
    const Eigen::Vector2d rotated = Eigen::Rotation2Dd(phi) * q.head<2>();
    VectorXd qr(4);
    qr << rotated, phi, phi;
    system.find_contacts(qr, VectorXd::Zero(4), 0.0, contacts);
    EXPECT_NEAR(contacts[0].gap, contacts[1].gap, 1e-15);
    EXPECT_NEAR(contacts[0].gap, q(1) - p.box_height / 2 - p.plank_thickness / 2, 1e-15);
  }
}

TEST(PlankBoxContacts, NamesKeysAndWorldGeometry) {
  const System system;
  const PlankBoxParameters& p = system.parameters();
  VectorXd q(4), v = VectorXd::Zero(4);
  q << 0.5, 3.0, 0.3, -0.2;  // far above the plank: both contacts are still reported
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, 0.0, contacts);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(contacts[0].name, "C_L");
  EXPECT_EQ(contacts[1].name, "C_R");
  EXPECT_NE(contacts[0].key, contacts[1].key);
  for (int k = 0; k < 2; ++k) {
    const Contact<double>& c = contacts[k];
    EXPECT_EQ(c.tangent_dim(), 1);
    EXPECT_EQ(c.friction, p.friction);
    EXPECT_EQ(c.restitution, p.restitution);
    const double side = k == 0 ? -1.0 : 1.0;
    const Eigen::Vector2d corner =
        q.head<2>() +
        Eigen::Rotation2Dd(q(2)) * Eigen::Vector2d(side * p.box_length / 2, -p.box_height / 2);
    EXPECT_NEAR((c.point.head<2>() - corner).norm(), 0.0, 1e-15);
    EXPECT_NEAR((c.normal.head<2>() - Eigen::Vector2d(-std::sin(q(3)), std::cos(q(3)))).norm(), 0.0,
                1e-15);
  }
  // C_L is the hinge-side corner: with the box level, it is nearer the hinge along the plank.
  q << 0.5, 0.3, 0.0, 0.0;
  system.find_contacts(q, v, 0.0, contacts);
  EXPECT_LT(contacts[0].point.x(), contacts[1].point.x());
}

// ---------------------------------------------------------------------------------------------
// Dynamics against the Lagrangian

TEST(PlankBoxDynamics, MassMatrixIsHessianOfKineticEnergy) {
  const System system;
  std::mt19937 rng(3);
  double worst = 0;
  for (int sample = 0; sample < 20; ++sample) {
    const State s = random_state(rng);
    const auto kinetic_gradient = [&](const VectorXd& v) {
      return central_gradient([&](const VectorXd& w) { return system.energy(s.q, w); }, v,
                              kVelocityStep2);
    };
    const MatrixXd hessian = central_jacobian(kinetic_gradient, s.v, kVelocityStep2);
    const MatrixXd M(system.mass_matrix(s.q));
    worst = std::max(worst, (M - hessian).norm() / M.norm());
    EXPECT_TRUE(M.isApprox(M.transpose()));
  }
  std::cout << "max relative |M - d2E/dv2| " << worst << "\n";
  EXPECT_LT(worst, kFdTolerance);
}

// H(q, v) = (∂²T/∂v∂q) v − ∂T/∂q + ∂V/∂q + ∂R/∂v with T = E(q,v) − E(q,0), V = E(q,0) and the
// damper's Rayleigh function R = ½ b_P φ̇²: the sign convention of B.2.
TEST(PlankBoxDynamics, BiasForcesFollowFromLagrangian) {
  const System system;
  const double b = system.parameters().plank_damping;
  ASSERT_GT(b, 0.0);
  std::mt19937 rng(4);
  double worst = 0;
  for (int sample = 0; sample < 20; ++sample) {
    const State s = random_state(rng);
    const auto potential = [&](const VectorXd& q) { return system.energy(q, VectorXd::Zero(4)); };
    const auto kinetic = [&](const VectorXd& q, const VectorXd& v) {
      return system.energy(q, v) - potential(q);
    };
    const auto momentum = [&](const VectorXd& q) {
      return central_gradient([&](const VectorXd& v) { return kinetic(q, v); }, s.v,
                              kVelocityStep2);
    };
    VectorXd expected = central_jacobian(momentum, s.q, kPositionStep2) * s.v -
                        central_gradient([&](const VectorXd& q) { return kinetic(q, s.v); }, s.q) +
                        central_gradient(potential, s.q);
    expected(3) += b * s.v(3);
    worst = std::max(worst, relative_error(system.bias_forces(s.q, s.v), expected));
  }
  std::cout << "max relative |H - H_Lagrange| " << worst << "\n";
  EXPECT_LT(worst, kFdTolerance);
}

// The damper's ∂H/∂v = ∂²R/∂v² = b_P e_φ e_φᵀ, which a time stepper takes implicitly: the system
// must say it has one, or the stepper never asks for it.
TEST(PlankBoxDynamics, SaysItHasTheDampingMatrixOfItsDamper) {
  const System system;
  ASSERT_TRUE(system.has_damping_matrix());
  std::mt19937 rng(5);
  const State s = random_state(rng);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(4, 4);
  expected(3, 3) = system.parameters().plank_damping;
  EXPECT_EQ(Eigen::MatrixXd(system.damping_matrix(s.q, s.v)), expected);
}

TEST(PlankBoxDynamics, EnergyConservedWithoutDampingContactOrInput) {
  PlankBoxParameters p;
  p.plank_damping = 0.0;
  const System system(p);
  const VectorXd u = VectorXd::Zero(3);
  VectorXd x0(8);
  x0 << 0.4, 1.0, 0.2, 0.3, 0.5, 1.0, -2.0, 1.0;
  const double e0 = system.energy(x0.head(4), x0.tail(4));
  ASSERT_GT(std::abs(e0), 1.0);
  double worst = 0;
  double min_phi = 1e9, max_phi = -1e9;
  integrate_rk4([&](double, const VectorXd& x) { return flow(system, x, u); }, 0.0, x0, 2.0, 20000,
                [&](double, const VectorXd& x) {
                  worst = std::max(worst, std::abs(system.energy(x.head(4), x.tail(4)) - e0));
                  min_phi = std::min(min_phi, x(3));
                  max_phi = std::max(max_phi, x(3));
                });
  std::cout << "E0 = " << e0 << " J, max |E - E0| / |E0| = " << worst / std::abs(e0)
            << ", phi swept [" << min_phi << ", " << max_phi << "]\n";
  EXPECT_GT(max_phi - min_phi, 0.2);  // the plank really oscillates through the nonlinearity
  EXPECT_LT(worst / std::abs(e0), 1e-8);
}

// dE/dt = vᵀ S u − b_P φ̇²: integrated along an RK4 trajectory with damping and constant input.
TEST(PlankBoxDynamics, EnergyBalanceWithDampingAndInput) {
  const System system;
  const double b = system.parameters().plank_damping;
  const VectorXd u = (VectorXd(3) << 3.0, 12.0, -0.5).finished();
  VectorXd x0(8);
  x0 << 0.4, 1.0, 0.2, 0.3, 0.5, 1.0, -2.0, 1.0;
  const int steps = 20000;
  const double h = 2.0 / steps;
  double work = 0, gross = 0, previous_power = 0;
  bool first = true;
  const VectorXd x1 = integrate_rk4(
      [&](double, const VectorXd& x) { return flow(system, x, u); }, 0.0, x0, 2.0, steps,
      [&](double, const VectorXd& x) {
        const VectorXd q = x.head(4), v = x.tail(4);
        const double power = v.dot(system.input_matrix(q) * u) - b * v(3) * v(3);
        if (!first) work += 0.5 * h * (power + previous_power);  // trapezoid, error O(h²)
        gross += h * std::abs(power);
        previous_power = power;
        first = false;
      });
  const double change =
      system.energy(x1.head(4), x1.tail(4)) - system.energy(x0.head(4), x0.tail(4));
  std::cout << "energy change " << change << " J, integrated power " << work
            << " J, relative mismatch " << std::abs(change - work) / gross << "\n";
  EXPECT_LT(std::abs(change - work) / gross, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// Automatic differentiation (for the sensitivity module): ∂f/∂x, ∂f/∂u, ∂γ/∂x.

TEST(PlankBoxAutoDiff, JacobiansEqualFiniteDifferences) {
  const System system;
  const AutoDiffSystem ad_system;
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> input(-5.0, 5.0);
  double worst_fx = 0, worst_fu = 0, worst_gap = 0, worst_drift = 0, worst_value = 0;
  for (int sample = 0; sample < 20; ++sample) {
    const State s = random_state(rng);
    VectorXd x(8), u(3);
    x << s.q, s.v;
    u << input(rng), input(rng), input(rng);

    // Seed the 11 directions (x, u).
    Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> x_ad(8), u_ad(3);
    for (int i = 0; i < 8; ++i) x_ad(i) = AutoDiff(x(i), 11, i);
    for (int i = 0; i < 3; ++i) u_ad(i) = AutoDiff(u(i), 11, 8 + i);

    const auto f_ad = flow(ad_system, x_ad, u_ad);
    MatrixXd df(8, 11);
    for (int r = 0; r < 8; ++r) {
      df.row(r) = f_ad(r).derivatives().transpose();
      worst_value = std::max(worst_value, std::abs(f_ad(r).value() - flow(system, x, u)(r)));
    }
    const MatrixXd fd_fx =
        central_jacobian([&](const VectorXd& y) { return flow(system, y, u); }, x);
    const MatrixXd fd_fu =
        central_jacobian([&](const VectorXd& w) { return flow(system, x, w); }, u);
    worst_fx = std::max(worst_fx, (df.leftCols(8) - fd_fx).norm() / fd_fx.norm());
    worst_fu = std::max(worst_fu, (df.rightCols(3) - fd_fu).norm() / fd_fu.norm());

    std::vector<Contact<AutoDiff>> ad_contacts;
    ad_system.find_contacts(x_ad.head(4), x_ad.tail(4), 0.0, ad_contacts);
    for (int k = 0; k < 2; ++k) {
      const auto gamma = [&](const VectorXd& y) {
        std::vector<Contact<double>> contacts;
        system.find_contacts(y.head(4), y.tail(4), 0.0, contacts);
        return VectorXd((VectorXd(2) << contacts[k].gap, contacts[k].normal_drift).finished());
      };
      const MatrixXd fd = central_jacobian(gamma, x);
      const VectorXd d_gap = ad_contacts[k].gap.derivatives().head(8);
      const VectorXd d_drift = ad_contacts[k].normal_drift.derivatives().head(8);
      worst_gap = std::max(worst_gap, relative_error(d_gap, fd.row(0).transpose()));
      worst_drift = std::max(worst_drift, relative_error(d_drift, fd.row(1).transpose()));
      worst_value = std::max(worst_value, std::abs(ad_contacts[k].gap.value() - gamma(x)(0)));
    }
  }
  std::cout << "max relative AD-vs-FD: df/dx " << worst_fx << ", df/du " << worst_fu << ", dgap/dx "
            << worst_gap << ", d(w_n_dot'v)/dx " << worst_drift << "; max |AD value - double| "
            << worst_value << "\n";
  EXPECT_LT(worst_fx, kFdTolerance);
  EXPECT_LT(worst_fu, kFdTolerance);
  EXPECT_LT(worst_gap, kFdTolerance);
  EXPECT_LT(worst_drift, kFdTolerance);
  EXPECT_LT(worst_value, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// The text's local-coordinate model (F.7–F.11, F.25/F.26) against ours: its M_l and S_l are our
// M and S pulled back through q_g(q_l) (so F's input is a world-frame force), and its gap
// formulas F.25/F.26 (as opposed to its corner positions F.23/F.24) agree with ours.

TEST(PlankBoxText, LocalModelIsPullBackOfGlobalModel) {
  const System system;
  const PlankBoxParameters& p = system.parameters();
  const double mB = p.box_mass, JB = p.box_inertia(), JH = p.plank_hinge_inertia();
  const double LB = p.box_length, lB = p.box_height, lP = p.plank_thickness;
  const auto global_from_local = [](const VectorXd& ql) {  // F.7
    const double c = std::cos(ql(3)), s = std::sin(ql(3));
    return VectorXd(
        (VectorXd(4) << c * ql(0) - s * ql(1), s * ql(0) + c * ql(1), ql(2) + ql(3), ql(3))
            .finished());
  };
  std::mt19937 rng(8);
  for (int sample = 0; sample < 20; ++sample) {
    const VectorXd ql = random_state(rng).q;
    const double xl = ql(0), yl = ql(1), th = ql(2), c = std::cos(ql(3)), s = std::sin(ql(3));
    const MatrixXd J = central_jacobian(global_from_local, ql);
    const VectorXd qg = global_from_local(ql);
    MatrixXd M_text(4, 4), S_text(4, 3);  // F.9, F.11
    M_text << mB, 0, 0, -mB * yl, 0, mB, 0, mB * xl, 0, 0, JB, JB, -mB * yl, mB * xl, JB,
        JH + mB * (xl * xl + yl * yl) + JB;
    S_text << c, s, 0, -s, c, 0, 0, 0, 1, -yl * c - xl * s, xl * c - yl * s, 1;
    const MatrixXd M(system.mass_matrix(qg));
    EXPECT_LT((J.transpose() * M * J - M_text).norm(), 1e-8);
    EXPECT_LT((J.transpose() * system.input_matrix(qg) - S_text).norm(), 1e-8);

    std::vector<Contact<double>> contacts;
    system.find_contacts(qg, VectorXd::Zero(4), 0.0, contacts);
    const double g_n1 = yl - lP / 2 - std::sin(th) * LB / 2 - std::cos(th) * lB / 2;  // F.25
    const double g_n2 = yl - lP / 2 + std::sin(th) * LB / 2 - std::cos(th) * lB / 2;  // F.26
    EXPECT_NEAR(contacts[0].gap, g_n1, 1e-14);
    EXPECT_NEAR(contacts[1].gap, g_n2, 1e-14);

    // Contact directions in local coordinates: w_l = Jᵀ w. F.34 holds as printed; F.35 with its
    // first two columns swapped back and the corner signs of F.23/F.24 corrected.
    MatrixXd WN_text(2, 4), WT_corrected(2, 4);
    WN_text << 0, 1, -std::cos(th) * LB / 2 + std::sin(th) * lB / 2, 0,  //
        0, 1, std::cos(th) * LB / 2 + std::sin(th) * lB / 2, 0;
    WT_corrected << 1, 0, std::sin(th) * LB / 2 + std::cos(th) * lB / 2, 0,  //
        1, 0, -std::sin(th) * LB / 2 + std::cos(th) * lB / 2, 0;
    for (int k = 0; k < 2; ++k) {
      EXPECT_LT(
          (J.transpose() * contacts[k].normal_direction(4) - WN_text.row(k).transpose()).norm(),
          1e-8);
      EXPECT_LT(
          (J.transpose() * contacts[k].tangent_directions(4) - WT_corrected.row(k).transpose())
              .norm(),
          1e-8);
    }
  }
}

// F.8/F.10 in local coordinates, with F.5's spring sign corrected (restoring −k_P φ, in F's
// M v̇ − H = S u convention), are satisfied by our global accelerations mapped to local ones:
// v̇_g = J v̇_l + J̇ v_l with J = ∂q_g/∂q_l of F.7.
TEST(PlankBoxText, LocalEquationsOfMotionHoldWithRestoringSpring) {
  const System system;
  const PlankBoxParameters& p = system.parameters();
  const double mB = p.box_mass, JB = p.box_inertia(), JH = p.plank_hinge_inertia();
  const double g = p.gravity, k = p.plank_stiffness, b = p.plank_damping;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> input(-5.0, 5.0);
  double worst = 0;
  for (int sample = 0; sample < 20; ++sample) {
    const State local = random_state(rng);
    const double xl = local.q(0), yl = local.q(1), phi = local.q(3);
    const double xd = local.v(0), yd = local.v(1), phd = local.v(3);
    const double c = std::cos(phi), s = std::sin(phi);
    const VectorXd u = (VectorXd(3) << input(rng), input(rng), input(rng)).finished();

    MatrixXd J(4, 4);
    J << c, -s, 0, -s * xl - c * yl, s, c, 0, c * xl - s * yl, 0, 0, 1, 1, 0, 0, 0, 1;
    VectorXd Jdot_v = VectorXd::Zero(4);
    Jdot_v(0) = -2 * phd * (s * xd + c * yd) - phd * phd * (c * xl - s * yl);
    Jdot_v(1) = 2 * phd * (c * xd - s * yd) - phd * phd * (s * xl + c * yl);
    VectorXd qg(4);
    qg << c * xl - s * yl, s * xl + c * yl, local.q(2) + phi, phi;
    const VectorXd vg = J * local.v;
    const VectorXd x = (VectorXd(8) << qg, vg).finished();
    const VectorXd vdot_g = flow(system, x, u).tail(4);
    const VectorXd vdot_l = J.partialPivLu().solve(vdot_g - Jdot_v);

    MatrixXd M_l(4, 4), S_l(4, 3);  // F.9, F.11
    M_l << mB, 0, 0, -mB * yl, 0, mB, 0, mB * xl, 0, 0, JB, JB, -mB * yl, mB * xl, JB,
        JH + mB * (xl * xl + yl * yl) + JB;
    S_l << c, s, 0, -s, c, 0, 0, 0, 1, -yl * c - xl * s, xl * c - yl * s, 1;
    VectorXd H_l(4);  // F.10 with −k_P φ
    H_l << mB * (xl * phd * phd + 2 * yd * phd - g * s),
        -mB * (-yl * phd * phd + 2 * xd * phd + g * c), 0,
        -k * phi - b * phd - 2 * mB * phd * xl * xd - 2 * mB * phd * yl * yd -
            p.plank_length * g * p.plank_mass * c / 2 - g * mB * xl * c + g * mB * yl * s;
    const VectorXd rhs = S_l * u;
    worst = std::max(worst, relative_error(VectorXd(M_l * vdot_l - H_l), rhs));
  }
  std::cout << "max relative residual of F.8 (spring corrected) " << worst << "\n";
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
}  // namespace impactbench::model
