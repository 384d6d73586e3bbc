// The spatial system instantiated with Eigen::AutoDiffScalar: its derivatives must agree with the
// analytic Jacobians of the double instantiation and with central finite differences.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/model/spatial/spatial_system_autodiff.hpp"
#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/random_poses.hpp"

namespace impactbench::model::spatial {
namespace {

using Ad = AutoDiff;
using AdVector = Eigen::Matrix<Ad, Eigen::Dynamic, 1>;
using test_support::central_difference;
using test_support::random_unit_quaternion;
using test_support::random_vector;

// A sphere resting near a cuboid and a tilted floor: exercises every contact type but cuboid
// pairs.
SpatialSystemSpec scene() {
  SpatialSystemSpec spec;
  BodySpec box;
  box.name = "box";
  box.shape = ShapeKind::kCuboid;
  box.size = Eigen::Vector3d(0.4, 0.6, 0.3);
  box.mass = 3.0;
  BodySpec ball;
  ball.name = "ball";
  ball.shape = ShapeKind::kSphere;
  ball.radius = 0.2;
  ball.mass = 1.0;
  BodySpec ball2 = ball;
  ball2.name = "ball2";
  spec.bodies = {box, ball, ball2};
  StaticPlaneSpec ground;
  ground.point = Eigen::Vector3d(0, 0, -0.5);
  ground.normal = Eigen::Vector3d(0.1, -0.2, 1.0).normalized();
  spec.planes = {ground};
  return spec;
}

struct State {
  Eigen::VectorXd q, v;
};

State random_state(std::mt19937& rng) {
  State s{Eigen::VectorXd(21), Eigen::VectorXd(18)};
  s.q << Eigen::Vector3d::Zero(), random_unit_quaternion(rng),  // box
      Eigen::Vector3d(0.35, 0.1, 0.05) + random_vector(rng, 0.05), random_unit_quaternion(rng),
      Eigen::Vector3d(0.3, 0.2, 0.5) + random_vector(rng, 0.05), random_unit_quaternion(rng);
  for (int i = 0; i < 18; ++i) s.v(i) = random_vector(rng, 2.0)(0);
  return s;
}

// x as autodiff constants (no derivatives).
AdVector constant(const Eigen::VectorXd& x) {
  return x.cast<Ad>();
}

// x with the identity as derivatives: differentiation with respect to every entry.
AdVector variables(const Eigen::VectorXd& x) {
  AdVector a(x.size());
  for (int i = 0; i < x.size(); ++i) a(i) = Ad(x(i), x.size(), i);
  return a;
}

TEST(SpatialAutodiff, GapDerivativeAlongVelocitiesIsTheNormalDirection) {
  const SpatialRigidBodySystem<double> plain(scene());
  const SpatialRigidBodySystem<Ad> ad(scene());
  std::mt19937 rng(1);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const State s = random_state(rng);
    Eigen::VectorXd dv(18);
    for (int i = 0; i < 18; ++i) dv(i) = random_vector(rng, 1.0)(0);
    // ε as the single AD variable: d/dε h(q ⊕ ε δv) at ε = 0 (through the exp-map series).
    const Ad eps(0.0, 1, 0);
    const AdVector q_eps = ad.integrate_position(constant(s.q), constant(dv), eps);
    std::vector<Contact<Ad>> ad_contacts;
    ad.find_contacts(q_eps, constant(s.v), 1e3, ad_contacts);
    std::vector<Contact<double>> contacts, perturbed;
    plain.find_contacts(s.q, s.v, 1e3, contacts);
    ASSERT_EQ(ad_contacts.size(), contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      ASSERT_EQ(ad_contacts[k].key, contacts[k].key);
      const double analytic = contacts[k].normal_direction(18).dot(dv);
      const double fd = central_difference(
          [&](double e) {
            plain.find_contacts(plain.integrate_position(s.q, dv, e), s.v, 1e3, perturbed);
            return perturbed[k].gap;
          },
          1e-6);
      const double derivative = ad_contacts[k].gap.derivatives()(0);
      EXPECT_NEAR(derivative, analytic, 1e-12 * std::max(1.0, std::abs(analytic)));
      EXPECT_NEAR(derivative, fd, 1e-6 * std::max(1.0, std::abs(analytic)));
      ++checked;
    }
  }
  EXPECT_GE(checked, 20 * 11);  // 8 corners, 2 spheres on the floor, sphere pairs and sphere–box
}

TEST(SpatialAutodiff, BiasForceJacobianMatchesFiniteDifferences) {
  const SpatialRigidBodySystem<double> plain(scene());
  const SpatialRigidBodySystem<Ad> ad(scene());
  std::mt19937 rng(2);
  for (int trial = 0; trial < 20; ++trial) {
    const State s = random_state(rng);
    const AdVector H = ad.bias_forces(constant(s.q), variables(s.v));
    for (int j = 0; j < 18; ++j) {
      const Eigen::VectorXd fd = central_difference(
          [&](double e) -> Eigen::VectorXd {
            return plain.bias_forces(s.q, s.v + e * Eigen::VectorXd::Unit(18, j));
          },
          1e-6);
      for (int i = 0; i < 18; ++i) {
        const double d = H(i).derivatives().size() ? H(i).derivatives()(j) : 0.0;
        EXPECT_NEAR(d, fd(i), 1e-6 * std::max(1.0, std::abs(fd(i))));
      }
    }
  }
}

TEST(SpatialAutodiff, EnergyGradientMatchesFiniteDifferencesAndKineticPartIsMv) {
  const SpatialRigidBodySystem<double> plain(scene());
  const SpatialRigidBodySystem<Ad> ad(scene());
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const State s = random_state(rng);
    // ∂E/∂v = M v.
    const Ad e_v = ad.energy(constant(s.q), variables(s.v));
    const Eigen::VectorXd Mv = plain.mass_matrix(s.q) * s.v;
    EXPECT_LT((e_v.derivatives() - Mv).norm(), 1e-12 * Mv.norm());
    // d/dε E(q ⊕ ε δv, v) by AD and FD.
    Eigen::VectorXd dv(18);
    for (int i = 0; i < 18; ++i) dv(i) = random_vector(rng, 1.0)(0);
    const Ad eps(0.0, 1, 0);
    const Ad e_q =
        ad.energy(ad.integrate_position(constant(s.q), constant(dv), eps), constant(s.v));
    const double fd = central_difference(
        [&](double e) { return plain.energy(plain.integrate_position(s.q, dv, e), s.v); }, 1e-6);
    EXPECT_NEAR(e_q.derivatives()(0), fd, 1e-6 * std::max(1.0, std::abs(fd)));
  }
}

TEST(SpatialAutodiff, IntegratePositionDerivativeAtZeroStepIsPositionRate) {
  const SpatialRigidBodySystem<double> plain(scene());
  const SpatialRigidBodySystem<Ad> ad(scene());
  std::mt19937 rng(4);
  const State s = random_state(rng);
  const AdVector next = ad.integrate_position(constant(s.q), constant(s.v), Ad(0.0, 1, 0));
  Eigen::VectorXd derivative(21);
  for (int i = 0; i < 21; ++i) derivative(i) = next(i).derivatives()(0);
  EXPECT_LT((derivative - plain.position_rate(s.q, s.v)).norm(), 1e-14);
}

}  // namespace
}  // namespace impactbench::model::spatial
