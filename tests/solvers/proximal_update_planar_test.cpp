// The planar proximal update in scalars (prox-gs's sweep over a factored problem) against the
// update on small vectors that prox-jacobi and the formed sweep use: the same bits in each of
// its cases (inside the disk, projected onto its boundary, a disk of radius zero).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "solvers/friction/proximal_point.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

TEST(ProximalUpdatePlanar, GivesTheVectorUpdatesBitsInEveryCase) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  std::uniform_real_distribution<double> positive(0.01, 3.0);
  std::uniform_real_distribution<double> friction(0.0, 1.5);
  std::uniform_real_distribution<double> relaxation(0.05, 1.9);
  int inside = 0, projected = 0, zero_radius = 0;
  for (int trial = 0; trial < 100000; ++trial) {
    // One in ten contacts without friction: the disk has radius zero.
    const double mu = trial % 10 == 0 ? 0.0 : friction(random);
    const AlartCurnierParameters rho{positive(random), positive(random)};
    const double omega = relaxation(random);
    const double r_n = value(random), r_t = value(random);
    const double u_n = value(random), u_t = value(random);
    LocalVector r(2), u(2);
    r << r_n, r_t;
    u << u_n, u_t;
    const LocalVector expected = proximal_update(mu, rho, omega, r, u);
    double n = r_n, t = r_t;
    proximal_update_planar(mu, rho, omega, n, t, u_n, u_t);
    ASSERT_EQ(n, expected(0)) << trial;
    ASSERT_EQ(t, expected(1)) << trial;
    const double radius = mu * expected(0);
    const double unprojected = r_t - omega * rho.rho_t * u_t;
    if (radius <= 0.0)
      ++zero_radius;
    else if (std::abs(unprojected) <= radius)
      ++inside;
    else
      ++projected;
  }
  // Each case met often enough that the comparison above covers it.
  EXPECT_GT(inside, 10000);
  EXPECT_GT(projected, 10000);
  EXPECT_GT(zero_radius, 10000);
}

}  // namespace
}  // namespace impactbench::solvers::friction_detail
