// Quaternion kinematics and the tangent frame of the spatial model.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/model/spatial/spatial_system.hpp"
#include "lib/model/spatial/tangent_frame.hpp"
#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/random_poses.hpp"

namespace impactbench::model::spatial {
namespace {

using test_support::central_difference;
using test_support::random_unit_quaternion;
using test_support::random_vector;

SpatialSystemSpec one_cuboid() {
  SpatialSystemSpec spec;
  BodySpec b;
  b.name = "box";
  b.shape = ShapeKind::kCuboid;
  b.size = Eigen::Vector3d(0.1, 0.2, 0.4);
  b.mass = 2.0;
  spec.bodies.push_back(b);
  return spec;
}

TEST(SpatialKinematics, RotationMatrixMatchesEigenQuaternion) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector4d q = random_unit_quaternion(rng);
    const Eigen::Matrix3d expected = Eigen::Quaterniond(q(0), q(1), q(2), q(3)).toRotationMatrix();
    EXPECT_LT((rotation_matrix<double>(q) - expected).norm(), 1e-14);
  }
}

TEST(SpatialKinematics, IntegrationIsTheExactRotationAboutTheWorldAxis) {
  // For constant world-frame ω, R(t) = exp(t [ω]×) R(0): a rotation by |ω| t about ω.
  std::mt19937 rng(2);
  SpatialRigidBodySystem<double> system(one_cuboid());
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::VectorXd q(7), v(6);
    q << random_vector(rng, 1.0), random_unit_quaternion(rng);
    v << random_vector(rng, 2.0), random_vector(rng, 3.0);
    const double h = 0.37;
    const Eigen::VectorXd next = system.integrate_position(q, v, h);
    const Eigen::Vector3d w = v.tail<3>();
    const Eigen::Matrix3d expected =
        Eigen::AngleAxisd(w.norm() * h, w.normalized()).toRotationMatrix() *
        rotation_matrix<double>(q.segment<4>(3));
    EXPECT_LT((rotation_matrix<double>(next.segment<4>(3)) - expected).norm(), 1e-13);
    EXPECT_LT((next.head<3>() - (q.head<3>() + h * v.head<3>())).norm(), 1e-14);
  }
}

TEST(SpatialKinematics, IntegratePositionHasPositionRateAsDerivative) {
  std::mt19937 rng(3);
  SpatialRigidBodySystem<double> system(one_cuboid());
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::VectorXd q(7), v(6);
    q << random_vector(rng, 1.0), random_unit_quaternion(rng);
    v << random_vector(rng, 2.0), random_vector(rng, 3.0);
    const Eigen::VectorXd fd = central_difference(
        [&](double e) -> Eigen::VectorXd { return system.integrate_position(q, v, e); }, 1e-6);
    EXPECT_LT((fd - system.position_rate(q, v)).norm(), 1e-8 * v.norm());
  }
}

TEST(SpatialKinematics, QuaternionStaysUnitOverHundredThousandSteps) {
  std::mt19937 rng(4);
  SpatialRigidBodySystem<double> system(one_cuboid());
  Eigen::VectorXd q = system.initial_positions();
  Eigen::VectorXd v(6);
  double worst = 0.0;
  for (int step = 0; step < 100000; ++step) {
    if (step % 1000 == 0) v << random_vector(rng, 1.0), random_vector(rng, 20.0);
    q = system.integrate_position(q, v, 1e-3);
    worst = std::max(worst, std::abs(q.segment<4>(3).norm() - 1.0));
  }
  std::printf("worst | |quat| - 1 | over 1e5 steps: %.3g\n", worst);
  EXPECT_LE(worst, 1e-14);
  // The rotation really happened (the map is not the identity).
  EXPECT_GT((q.segment<4>(3) - system.initial_positions().segment<4>(3)).norm(), 1e-3);
}

TEST(SpatialKinematics, TangentFrameIsOrthonormalRightHandedAndItsRateMatchesFd) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 400; ++trial) {
    const Eigen::Vector3d n = random_vector(rng, 1.0).normalized();
    if (std::abs(n.z() + 0.5) < 1e-3) continue;  // the frame switches caps at n_z = −½
    Eigen::Vector3d n_rate = random_vector(rng, 1.0);
    n_rate -= n * n.dot(n_rate);
    const TangentFrame<double> f = tangent_frame<double>(n, n_rate);
    Eigen::Matrix3d basis;
    basis << n, f.t1, f.t2;
    EXPECT_LT((basis.transpose() * basis - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_LT((f.t1.cross(f.t2) - n).norm(), 1e-14);
    // n(s) = normalize(n + s ṅ) has rate ṅ at s = 0.
    const auto frame_at = [&](double s) -> Eigen::VectorXd {
      const TangentFrame<double> g =
          tangent_frame<double>((n + s * n_rate).normalized(), Eigen::Vector3d::Zero().eval());
      Eigen::VectorXd t(6);
      t << g.t1, g.t2;
      return t;
    };
    Eigen::VectorXd analytic(6);
    analytic << f.t1_rate, f.t2_rate;
    EXPECT_LT((central_difference(frame_at, 1e-6) - analytic).norm(),
              1e-7 * std::max(1.0, analytic.norm()));
  }
}

TEST(SpatialKinematics, TangentFrameOfFloorIsTheWorldAxes) {
  const TangentFrame<double> up =
      tangent_frame<double>(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero().eval());
  EXPECT_EQ(up.t1, Eigen::Vector3d::UnitX());
  EXPECT_EQ(up.t2, Eigen::Vector3d::UnitY());
  const TangentFrame<double> down =
      tangent_frame<double>((-Eigen::Vector3d::UnitZ()).eval(), Eigen::Vector3d::Zero().eval());
  EXPECT_EQ(down.t1, Eigen::Vector3d::UnitX());
  EXPECT_EQ(down.t2, -Eigen::Vector3d::UnitY());
}

}  // namespace
}  // namespace impactbench::model::spatial
