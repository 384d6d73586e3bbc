// Initial states from a toss: body → world angular velocity, the fit of the free flight, and the
// cube_toss scenario parameters they set.
#include <cmath>

#include <gtest/gtest.h>

#include "lib/validation/toss_state.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::validation {
namespace {

constexpr double kSide = 0.1048;

TEST(TossState, AngularVelocityIsTurnedFromTheBodyIntoTheWorldFrame) {
  // A quarter turn about z maps the body's x axis onto the world's y axis, y onto −x:
  // ω_body = (1, 2, 3) is ω_world = (−2, 1, 3).
  TossSample s;
  s.orientation = Eigen::Quaterniond(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
  s.angular_velocity_body = Eigen::Vector3d(1, 2, 3);
  Toss toss{"hand", {s, s}};
  const InitialState state = sample_state(toss, 1);
  EXPECT_NEAR((state.angular_velocity - Eigen::Vector3d(-2, 1, 3)).norm(), 0.0, 1e-15);
  // A half turn about x: (y, z) → (−y, −z).
  toss.samples[0].orientation = Eigen::Quaterniond(0, 1, 0, 0);
  EXPECT_NEAR((sample_state(toss, 0).angular_velocity - Eigen::Vector3d(1, -2, -3)).norm(), 0.0,
              1e-15);
  EXPECT_THROW(sample_state(toss, 2), std::out_of_range);
}

TEST(TossState, LowestCornerAndFirstContact) {
  // Level: half a side below the centre. Balanced on an edge (45° about x): side/√2 below.
  EXPECT_NEAR(lowest_corner_height({0, 0, 1}, Eigen::Quaterniond::Identity(), kSide), 1 - kSide / 2,
              1e-15);
  const Eigen::Quaterniond edge(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(lowest_corner_height({0, 0, 1}, edge, kSide), 1 - kSide / std::sqrt(2.0), 1e-15);
  Toss toss;
  for (const double z : {0.2, 0.1, 0.0580, 0.0570, 0.0524}) {
    TossSample s;
    s.position.z() = z;
    toss.samples.push_back(s);
  }
  // Corner heights 0.1476, 0.0476, 0.0056, 0.0046, 0 against board_offset + margin.
  EXPECT_EQ(first_contact_index(toss, CubeGeometry{}), 3u);                     // 0.005
  EXPECT_EQ(first_contact_index(toss, CubeGeometry{kSide, 0.001, 0.005}), 2u);  // 0.006
  EXPECT_EQ(first_contact_index(toss, CubeGeometry{kSide, -0.01, 0.005}), 5u);  // never
}

TEST(TossState, BallisticFitRecoversAnExactFreeFlight) {
  // p(t) = p0 + v0 t − g t²/2 e_z, q(t) = exp(ω t) q0 (constant world ω), sampled at 148 Hz;
  // lands when the lowest corner reaches the margin.
  const Eigen::Vector3d p0(0.2, -0.1, 0.2), v0(-1.0, 0.5, 0.3), omega(3.0, -2.0, 5.0);
  const Eigen::Quaterniond q0 = Eigen::Quaterniond(0.4, 0.2, 0.85, -0.03).normalized();
  const double g = 9.81;
  Toss toss{"synthetic", {}};
  for (int k = 0; k < 40; ++k) {
    const double t = k / 148.0;
    TossSample s;
    s.t = t;
    s.position = p0 + v0 * t - 0.5 * g * t * t * Eigen::Vector3d::UnitZ();
    const double angle = omega.norm() * t;
    s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega.normalized())) * q0;
    s.angular_velocity_body = s.orientation.conjugate() * omega;
    toss.samples.push_back(s);
  }
  const CubeGeometry cube;
  ASSERT_GE(first_contact_index(toss, cube), 10u);
  const InitialState fit = fitted_state(toss, cube, g);
  EXPECT_NEAR((fit.position - p0).norm(), 0.0, 1e-12);
  EXPECT_NEAR((fit.velocity - v0).norm(), 0.0, 1e-11);
  EXPECT_NEAR(fit.orientation.angularDistance(q0), 0.0, 1e-9);
  // Rotation vectors relative to q0 are exactly ω t: the linear fit is exact.
  EXPECT_NEAR((fit.angular_velocity - omega).norm(), 0.0, 1e-9);
  // The sample's own state agrees (ω_world = R ω_body).
  EXPECT_NEAR((sample_state(toss, 0).angular_velocity - omega).norm(), 0.0, 1e-12);
  // Too short a free flight is refused.
  toss.samples.resize(2);
  EXPECT_THROW(fitted_state(toss, cube, g), std::runtime_error);
}

TEST(TossState, ParametersSetTheCubeTossScenariosInitialState) {
  InitialState state;
  state.position = {0.1, 0.2, 0.3};
  state.orientation = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);  // w first
  state.velocity = {1, 2, 3};
  state.angular_velocity = {4, 5, 6};
  const auto s = scenario::load_scenario_by_name("cube_toss", state_parameters(state));
  ASSERT_EQ(s.bodies.size(), 1u);
  const auto& cube = s.bodies[0];
  EXPECT_EQ(cube.position, state.position);
  EXPECT_EQ(cube.orientation.w(), 0.5);
  EXPECT_EQ(cube.orientation.y(), -0.5);
  EXPECT_EQ(cube.velocity, state.velocity);
  EXPECT_EQ(cube.angular_velocity, state.angular_velocity);
  ASSERT_TRUE(cube.inertia.has_value());
  EXPECT_EQ(*cube.inertia, Eigen::Vector3d::Constant(8.10e-4));
  EXPECT_EQ(cube.size, Eigen::Vector3d::Constant(kSide));
  EXPECT_EQ(cube.mass, 0.37);
}

}  // namespace
}  // namespace impactbench::validation
