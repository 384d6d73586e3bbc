// Orientation errors as rotation distances, apart from positions: an engine that reports −q
// for the reference's q, or θ + 2π for θ, has no orientation error.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "lib/metrics/pose_error.hpp"

namespace impactbench::metrics {
namespace {

constexpr double kPi = std::numbers::pi;

// A sphere spinning about z at 5 rad/s while it moves along x at 1 m/s: columns
// x, y, z, qw, qx, qy, qz.
Eigen::VectorXd spinning(double t, double sign) {
  Eigen::VectorXd q(7);
  const double half = 0.5 * 5.0 * t;
  q << t, 0.2, 0.0, sign * std::cos(half), 0.0, 0.0, sign * std::sin(half);
  return q;
}

// `state(t)` at t = 0, 1/n, ..., 1 s.
template <typename State>
Signal sampled(int n, State state) {
  Signal signal;
  for (int i = 0; i <= n; ++i) {
    signal.times.push_back(static_cast<double>(i) / n);
    signal.values.push_back(state(signal.times.back()));
  }
  return signal;
}

const std::vector<std::string> kSphere{"ball.x",  "ball.y",  "ball.z", "ball.qw",
                                       "ball.qx", "ball.qy", "ball.qz"};

TEST(PoseError, MinusQIsTheSameRotation) {
  const Signal reference = sampled(200, [](double t) { return spinning(t, 1.0); });
  // From t = 0.6 s on, the engine reports −q, as Bullet did on sphere_spin.
  const Signal engine = sampled(200, [](double t) { return spinning(t, t >= 0.6 ? -1.0 : 1.0); });
  const PoseTrajectoryError e = pose_trajectory_error(engine, reference, pose_layout(kSphere));
  // Same rotations at the same samples: only round-off of the normalisation remains.
  EXPECT_LT(e.orientation.linf, 1e-7);
  EXPECT_LT(e.position.linf, 1e-12);
  // The component difference the old metric took: ‖q − (−q)‖ = 2.
  EXPECT_NEAR(trajectory_error(engine, reference).linf, 2.0, 1e-12);
}

TEST(PoseError, OrientationErrorIsTheAngleOfTheRelativeRotation) {
  const Signal reference = sampled(100, [](double t) { return spinning(t, 1.0); });
  // The engine lags by 0.1 s of spin (0.5 rad) and sits 3 mm higher, with −q throughout.
  const Signal engine = sampled(100, [](double t) {
    Eigen::VectorXd lagging = spinning(t - 0.1, -1.0);
    lagging.head<3>() = spinning(t, 1.0).head<3>() + Eigen::Vector3d(0.0, 0.003, 0.0);
    return lagging;
  });
  const PoseTrajectoryError e = pose_trajectory_error(engine, reference, pose_layout(kSphere));
  // Linear interpolation of the reference is exact at its own sample times.
  EXPECT_NEAR(e.orientation.linf, 0.5, 1e-9);
  EXPECT_NEAR(e.orientation.l1, 0.5 * 1.0, 1e-9);  // [rad·s]
  EXPECT_NEAR(e.position.linf, 0.003, 1e-12);      // [m], the angle not mixed in
}

TEST(PoseError, PlanarAnglesWrapAndPlankAngleIsAnAngle) {
  const PoseLayout layout = pose_layout({"box.x", "box.y", "box.theta", "plank.phi"});
  EXPECT_EQ(layout.positions, (std::vector<int>{0, 1}));
  EXPECT_EQ(layout.angles, (std::vector<int>{2, 3}));
  Signal reference{{0.0, 1.0}, {Eigen::Vector4d(0, 0, 0.1, 0.2), Eigen::Vector4d(0, 0, 0.1, 0.2)}};
  Signal engine{
      {0.0, 1.0},
      {Eigen::Vector4d(0, 0, 0.1 + 2 * kPi, 0.2), Eigen::Vector4d(0, 0, 0.1 - 4 * kPi, 0.23)}};
  const PoseTrajectoryError e = pose_trajectory_error(engine, reference, layout);
  EXPECT_NEAR(e.orientation.linf, 0.03, 1e-12);  // whole turns are no error
  EXPECT_NEAR(rotation_distance(kPi + 0.1, -kPi + 0.1), 0.0, 1e-15);
  EXPECT_NEAR(rotation_distance(3.0, -3.0), 2 * kPi - 6.0, 1e-15);
}

TEST(PoseError, RotationDistanceOfQuaternionsIsInZeroToPi) {
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond b(Eigen::AngleAxisd(-2.9, Eigen::Vector3d::UnitX()));
  // 0.3 − (−2.9) = 3.2 rad one way, 2π − 3.2 the other.
  EXPECT_NEAR(rotation_distance(a, b), 2 * kPi - 3.2, 1e-12);
  const Eigen::Quaterniond minus_a(-a.w(), -a.x(), -a.y(), -a.z());
  EXPECT_NEAR(rotation_distance(a, minus_a), 0.0, 1e-15);
}

TEST(PoseError, RefusesUnknownColumnsAndBrokenQuaternions) {
  EXPECT_THROW(pose_layout({"ball.x", "ball.speed"}), std::invalid_argument);
  EXPECT_THROW(pose_layout({"ball.qw", "ball.qx", "ball.qz", "ball.qy"}), std::invalid_argument);
  EXPECT_THROW(pose_layout({"ball.qw", "ball.qx"}), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::metrics
