// The free motion with M⁻¹ kept across steps: for a system whose M does not depend on q (the
// project's planar rigid bodies) the kept inverse gives v_free and Â⁻¹ bit for bit as a fresh
// inversion does at other states; a system that does not say its M is constant never keeps it.
#include <memory>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "lib/engines/moreau_jean/free_motion.hpp"
#include "tests/support/lib/moreau_planar_worlds.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using test_support::PlanarKind;

test_support::PlanarWorldSpec disk_and_box() {
  test_support::PlanarWorldSpec spec;
  spec.bodies = {test_support::disk("disk", 0.1, 2.0), test_support::box("box", 0.3, 0.2, 5.0)};
  return spec;
}

TEST(MoreauFreeMotion, AKeptMassInverseGivesTheFreshFreeMotion) {
  const auto system = test_support::make_planar_world(PlanarKind::kProjectSystem, disk_and_box());
  ASSERT_TRUE(system->mass_matrix_is_constant());
  const MoreauJeanOptions options;
  const double h = 1e-3;
  Eigen::VectorXd q(6), v(6);
  q << 0, 0.5, 0.1, 1, 0.4, -0.3;
  v << 1, -2, 3, -0.5, 0.2, 7;
  Eigen::SparseMatrix<double> kept;
  const FreeMotion first = compute_free_motion(*system, q, v, {}, h, options, &kept);
  ASSERT_EQ(first.kept_inverse, &kept);
  EXPECT_EQ(kept.rows(), 6);
  for (const double angle : {0.0, 1.0, -2.5}) {
    q(2) = angle;
    q(5) = 2 * angle;
    v(2) += 1.0;
    const FreeMotion fresh = compute_free_motion(*system, q, v, {}, h, options);
    const FreeMotion reused = compute_free_motion(*system, q, v, {}, h, options, &kept);
    EXPECT_EQ(fresh.kept_inverse, nullptr);
    EXPECT_EQ(reused.kept_inverse, &kept);
    EXPECT_EQ(reused.free_velocity, fresh.free_velocity);
    EXPECT_EQ(Eigen::MatrixXd(reused.inverse()), Eigen::MatrixXd(fresh.inverse()));
  }
}

TEST(MoreauFreeMotion, ASystemThatDoesNotSayItsMassIsConstantKeepsNothing) {
  const auto system = test_support::make_planar_world(PlanarKind::kTestWorld, disk_and_box());
  ASSERT_FALSE(system->mass_matrix_is_constant());
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Ones(6);
  Eigen::SparseMatrix<double> kept;
  const FreeMotion motion =
      compute_free_motion(*system, q, v, {}, 1e-3, MoreauJeanOptions{}, &kept);
  EXPECT_EQ(motion.kept_inverse, nullptr);
  EXPECT_EQ(kept.size(), 0);
  EXPECT_EQ(motion.inverse_iteration_matrix.rows(), 6);
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
