// Mass matrix, bias forces, inputs, energy and spec validation of the spatial model.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "lib/model/body_inertia.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "tests/support/lib/random_poses.hpp"
#include "tests/support/lib/rk4.hpp"

namespace impactbench::model::spatial {
namespace {

using System = SpatialRigidBodySystem<double>;
using test_support::random_unit_quaternion;
using test_support::random_vector;

BodySpec asymmetric_box() {
  BodySpec b;
  b.name = "brick";
  b.shape = ShapeKind::kCuboid;
  b.size = Eigen::Vector3d(0.1, 0.25, 0.4);
  b.mass = 2.0;
  return b;
}

BodySpec ball() {
  BodySpec b;
  b.name = "ball";
  b.shape = ShapeKind::kSphere;
  b.radius = 0.3;
  b.mass = 0.7;
  return b;
}

Eigen::Vector3d angular_momentum(const System& system, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& v) {
  const Eigen::MatrixXd M(system.mass_matrix(q));
  return M.block<3, 3>(3, 3) * v.segment<3>(3);
}

TEST(SpatialDynamics, MassMatrixHoldsMassAndRotatedPrincipalInertia) {
  SpatialSystemSpec spec;
  spec.bodies = {asymmetric_box(), ball()};
  const System system(spec);
  std::mt19937 rng(1);
  Eigen::VectorXd q(14);
  q << random_vector(rng, 1), random_unit_quaternion(rng), random_vector(rng, 1),
      random_unit_quaternion(rng);
  const Eigen::MatrixXd M(system.mass_matrix(q));
  const Eigen::Vector4d c = q.segment<4>(3);
  const Eigen::Matrix3d R = Eigen::Quaterniond(c(0), c(1), c(2), c(3)).toRotationMatrix();
  // Box m/12 (b² + c²) etc.; sphere 2/5 m r².
  const Eigen::Vector3d box_inertia(2.0 / 12 * (0.0625 + 0.16), 2.0 / 12 * (0.01 + 0.16),
                                    2.0 / 12 * (0.01 + 0.0625));
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(12, 12);
  expected.block<3, 3>(0, 0) = 2.0 * Eigen::Matrix3d::Identity();
  expected.block<3, 3>(3, 3) = R * box_inertia.asDiagonal() * R.transpose();
  expected.block<3, 3>(6, 6) = 0.7 * Eigen::Matrix3d::Identity();
  expected.block<3, 3>(9, 9) = 0.4 * 0.7 * 0.09 * Eigen::Matrix3d::Identity();
  EXPECT_LT((M - expected).norm(), 1e-15);
}

TEST(SpatialDynamics, GivenPrincipalInertiaReplacesTheUniformSolids) {
  // The recorded cube: uniform it would have 0.37/6 0.1048² = 6.7729e-4; given 8.10e-4.
  BodySpec cube = asymmetric_box();
  cube.size = Eigen::Vector3d::Constant(0.1048);
  cube.mass = 0.37;
  EXPECT_NEAR(principal_inertia(cube).x(), 0.37 / 6 * 0.1048 * 0.1048, 1e-18);
  EXPECT_NEAR(0.37 / 6 * 0.1048 * 0.1048, 6.7729e-4, 1e-8);
  cube.inertia = Eigen::Vector3d(8.10e-4, 8.10e-4, 9.0e-4);
  SpatialSystemSpec spec;
  spec.bodies = {cube};
  const System system(spec);
  Eigen::VectorXd q(7);
  q << 0, 0, 0, std::sqrt(0.5), std::sqrt(0.5), 0, 0;  // a quarter turn about x: z -> y
  const Eigen::MatrixXd M(system.mass_matrix(q));
  EXPECT_NEAR(M(3, 3), 8.10e-4, 1e-18);
  EXPECT_NEAR(M(4, 4), 9.0e-4, 1e-18);  // the body's z axis now lies along the world's y
  EXPECT_NEAR(M(5, 5), 8.10e-4, 1e-18);
  EXPECT_NEAR(M(0, 0), 0.37, 1e-18);
}

TEST(SpatialDynamics, EnergyIsHalfVMVPlusGravity) {
  SpatialSystemSpec spec;
  spec.bodies = {asymmetric_box(), ball()};
  spec.gravity = 9.81;
  const System system(spec);
  std::mt19937 rng(2);
  Eigen::VectorXd q(14), v(12);
  q << random_vector(rng, 1), random_unit_quaternion(rng), random_vector(rng, 1),
      random_unit_quaternion(rng);
  v = Eigen::VectorXd::NullaryExpr(12, [&] { return random_vector(rng, 2)(0); });
  const double expected = 0.5 * v.dot(system.mass_matrix(q) * v) + 9.81 * (2.0 * q(2) + 0.7 * q(9));
  EXPECT_NEAR(system.energy(q, v), expected, 1e-13);
}

TEST(SpatialDynamics, GyroscopicTermSatisfiesEulerEquationsInTheBodyFrame) {
  // With ω_b = Rᵀω: I_b ω̇_b + ω_b × I_b ω_b = 0, and ω̇ = R ω̇_b (the ω × ω term vanishes).
  SpatialSystemSpec spec;
  spec.bodies = {asymmetric_box()};
  spec.gravity = 0.0;
  const System system(spec);
  std::mt19937 rng(3);
  const Eigen::Vector3d I_b(2.0 / 12 * (0.0625 + 0.16), 2.0 / 12 * (0.01 + 0.16),
                            2.0 / 12 * (0.01 + 0.0625));
  for (int trial = 0; trial < 100; ++trial) {
    Eigen::VectorXd q(7), v(6);
    q << random_vector(rng, 1), random_unit_quaternion(rng);
    v << random_vector(rng, 1), random_vector(rng, 5);
    const Eigen::MatrixXd M(system.mass_matrix(q));
    const Eigen::VectorXd accel = M.ldlt().solve(-system.bias_forces(q, v));
    const Eigen::Matrix3d R = rotation_matrix<double>(q.segment<4>(3));
    const Eigen::Vector3d w_b = R.transpose() * v.tail<3>();
    const Eigen::Vector3d euler =
        I_b.asDiagonal() * (R.transpose() * accel.tail<3>()) + w_b.cross(I_b.asDiagonal() * w_b);
    EXPECT_LT(euler.norm(), 1e-12);
    EXPECT_LT(accel.head<3>().norm(), 1e-15);
  }
}

// Energy alone cannot catch a wrong sign of ω × I_w ω (ωᵀ(ω × a) = 0 either way); the world-frame
// angular momentum I_w ω can.
TEST(SpatialDynamics, FreeRotationConservesEnergyAndAngularMomentum) {
  SpatialSystemSpec spec;
  BodySpec b = asymmetric_box();
  std::mt19937 rng(4);
  const Eigen::Vector4d o = random_unit_quaternion(rng);
  b.orientation = Eigen::Quaterniond(o(0), o(1), o(2), o(3));
  b.angular_velocity = Eigen::Vector3d(1.0, 4.0, 2.0);  // large middle-axis share: tumbling
  b.velocity = Eigen::Vector3d(0.3, -0.2, 1.5);
  spec.bodies = {b};
  const System system(spec);
  Eigen::VectorXd q = system.initial_positions(), v = system.initial_velocities();
  const double e0 = system.energy(q, v);
  const auto rotational_energy = [&] {
    return system.energy(q, v) - 0.5 * 2.0 * v.head<3>().squaredNorm() - 2.0 * 9.81 * q(2);
  };
  const double r0 = rotational_energy();
  const Eigen::Vector3d l0 = angular_momentum(system, q, v);
  const Eigen::Vector3d w0 = v.tail<3>();
  double worst_energy = 0.0, worst_momentum = 0.0, worst_rotational = 0.0;
  const double h = 1e-3;
  for (int step = 0; step < 2000; ++step) {  // 2 s
    test_support::rk4_step(system, q, v, h);
    worst_energy = std::max(worst_energy, std::abs(system.energy(q, v) - e0) / std::abs(e0));
    worst_rotational = std::max(worst_rotational, std::abs(rotational_energy() - r0) / r0);
    worst_momentum =
        std::max(worst_momentum, (angular_momentum(system, q, v) - l0).norm() / l0.norm());
  }
  std::printf("free rotation over 2 s: energy %.3g, rotational energy %.3g, momentum %.3g\n",
              worst_energy, worst_rotational, worst_momentum);
  EXPECT_LT(worst_energy, 1e-8);
  EXPECT_LT(worst_rotational, 1e-8);
  EXPECT_LT(worst_momentum, 1e-8);
  EXPECT_GT((v.tail<3>() - w0).norm(), 0.1);  // the body really tumbled
  // Free fall of the centre: RK4 is exact on quadratics.
  EXPECT_NEAR(q(2), 1.5 * 2.0 - 0.5 * 9.81 * 4.0, 1e-10);
}

TEST(SpatialDynamics, GravityAndInputsEnterAsGeneralizedForces) {
  SpatialSystemSpec spec;
  spec.bodies = {asymmetric_box(), ball()};
  spec.gravity = 3.0;
  ForceInputSpec push;
  push.body = "ball";
  push.direction = Eigen::Vector3d(0.6, 0.0, 0.8);
  spec.inputs = {push};
  const System system(spec);
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd H = system.bias_forces(q, Eigen::VectorXd::Zero(12));
  Eigen::VectorXd expected_H = Eigen::VectorXd::Zero(12);
  expected_H(2) = 2.0 * 3.0;
  expected_H(8) = 0.7 * 3.0;
  EXPECT_LT((H - expected_H).norm(), 1e-15);
  const Eigen::MatrixXd S = system.input_matrix(q);
  ASSERT_EQ(S.rows(), 12);
  ASSERT_EQ(S.cols(), 1);
  Eigen::VectorXd expected_S = Eigen::VectorXd::Zero(12);
  expected_S.segment<3>(6) = push.direction;
  EXPECT_LT((S.col(0) - expected_S).norm(), 1e-15);
}

TEST(SpatialDynamics, NamesFollowTheTrajectoryCsvOrder) {
  SpatialSystemSpec spec;
  spec.bodies = {ball()};
  const System system(spec);
  EXPECT_EQ(system.position_names(),
            (std::vector<std::string>{"ball.x", "ball.y", "ball.z", "ball.qw", "ball.qx", "ball.qy",
                                      "ball.qz"}));
  EXPECT_EQ(system.velocity_names(), (std::vector<std::string>{"ball.vx", "ball.vy", "ball.vz",
                                                               "ball.wx", "ball.wy", "ball.wz"}));
  EXPECT_EQ(system.num_positions(), 7);
  EXPECT_EQ(system.num_velocities(), 6);
  EXPECT_EQ(system.tangent_dim(), 2);
}

// The constructor must reject `spec` with std::invalid_argument whose message names all of
// `words`.
void expect_rejected(const SpatialSystemSpec& spec, std::initializer_list<const char*> words) {
  try {
    const System system(spec);
    ADD_FAILURE() << "accepted a bad spec";
  } catch (const std::invalid_argument& e) {
    for (const char* w : words)
      EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
  }
}

TEST(SpatialDynamics, BadSpecsAreRejectedNamingBodyAndField) {
  const auto with = [](auto edit) {
    SpatialSystemSpec spec;
    spec.bodies = {asymmetric_box(), ball()};
    StaticPlaneSpec ground;
    ground.normal = Eigen::Vector3d::UnitZ();
    spec.planes = {ground};
    edit(spec);
    return spec;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(with([](auto& s) { s.bodies[1].mass = -1.0; }), {"ball", "mass"});
  expect_rejected(with([&](auto& s) { s.bodies[0].mass = nan; }), {"brick", "mass"});
  expect_rejected(with([](auto& s) { s.bodies[1].radius = 0.0; }), {"ball", "radius"});
  expect_rejected(with([](auto& s) { s.bodies[0].size.y() = 0.0; }), {"brick", "size"});
  expect_rejected(with([](auto& s) { s.bodies[0].orientation.coeffs() *= 1.1; }),
                  {"brick", "orientation"});
  expect_rejected(with([&](auto& s) { s.bodies[1].position.z() = nan; }), {"ball", "position"});
  expect_rejected(with([&](auto& s) { s.bodies[1].angular_velocity.x() = nan; }),
                  {"ball", "angular_velocity"});
  expect_rejected(with([](auto& s) { s.bodies[1].shape = ShapeKind::kDisk; }), {"ball", "shape"});
  expect_rejected(with([](auto& s) { s.bodies[0].inertia = Eigen::Vector3d(1, 1, 2.5); }),
                  {"brick", "inertia"});
  expect_rejected(with([&](auto& s) { s.bodies[0].inertia = Eigen::Vector3d(1, nan, 1); }),
                  {"brick", "inertia"});
  expect_rejected(with([](auto& s) { s.bodies[1].name = "brick"; }), {"brick", "name"});
  expect_rejected(with([](auto& s) { s.planes[0].normal = Eigen::Vector3d(0, 0, 2); }),
                  {"ground", "normal"});
  expect_rejected(with([](auto& s) { s.material.friction = -0.1; }), {"friction"});
  expect_rejected(with([](auto& s) { s.material.restitution = 1.5; }), {"restitution"});
  expect_rejected(with([](auto& s) {
                    ForceInputSpec in;
                    in.body = "ghost";
                    s.inputs = {in};
                  }),
                  {"ghost", "body"});
  // And the good one is accepted.
  EXPECT_NO_THROW(System(with([](auto&) {})));
}

TEST(SpatialDynamics, WrongStateSizesAreRejected) {
  SpatialSystemSpec spec;
  spec.bodies = {ball()};
  const System system(spec);
  const Eigen::VectorXd q = system.initial_positions(), v = system.initial_velocities();
  EXPECT_THROW(system.bias_forces(q, v.head(5)), std::invalid_argument);
  EXPECT_THROW(system.mass_matrix(q.head(6)), std::invalid_argument);
  EXPECT_THROW(system.energy(q, Eigen::VectorXd::Zero(7)), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model::spatial
