// A planar contact prepared once per solve (nsgs) against the same contact solved from W_ii:
// the same case (open, stick, slip either way, Newton) and the same impulse to round-off, and
// both solve the local problem.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "solvers/friction/single_contact_solver.hpp"

namespace impactbench::solvers {
namespace {

// Which case a planar impulse (r_n, r_t) of u = A r + b is.
enum class Case { kOpen, kStick, kSlipPositive, kSlipNegative };

Case case_of(double mu, double r_n, double r_t) {
  if (r_n == 0.0 && r_t == 0.0) return Case::kOpen;
  if (std::abs(r_t) < mu * r_n * (1.0 - 1e-9)) return Case::kStick;
  return r_t < 0.0 ? Case::kSlipPositive : Case::kSlipNegative;  // r_t = −σ μ r_n
}

TEST(PreparedPlanarContact, SolvesAsTheUnpreparedContactToRoundOffInEveryCase) {
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  std::uniform_real_distribution<double> friction(0.0, 1.5);
  int counts[4] = {};
  for (int trial = 0; trial < 20000; ++trial) {
    // A = J M⁻¹ Jᵀ of one contact between a disk and the ground: symmetric positive definite.
    Eigen::Matrix2d j;
    j << entry(random), entry(random), entry(random), entry(random);
    LocalMatrix a = j * j.transpose() + 1e-3 * Eigen::Matrix2d::Identity();
    const double mu = friction(random);
    const double b_n = entry(random), b_t = entry(random);
    double direct_n = 0.0, direct_t = 0.0, prepared_n = 0.0, prepared_t = 0.0;
    const bool direct_exact = solve_single_contact_planar(a, b_n, b_t, mu, direct_n, direct_t);
    const PreparedPlanarContact prepared = prepare_planar_contact(a, mu);
    const bool prepared_exact =
        solve_prepared_planar_contact(prepared, b_n, b_t, prepared_n, prepared_t);
    ASSERT_TRUE(direct_exact) << trial;
    ASSERT_TRUE(prepared_exact) << trial;
    const double size = std::abs(direct_n) + std::abs(direct_t) + 1e-300;
    EXPECT_LE(std::abs(prepared_n - direct_n), 1e-10 * size) << trial;
    EXPECT_LE(std::abs(prepared_t - direct_t), 1e-10 * size) << trial;
    const Case c = case_of(mu, direct_n, direct_t);
    EXPECT_EQ(case_of(mu, prepared_n, prepared_t), c) << trial;
    ++counts[static_cast<int>(c)];
    // Either answer solves the local problem: in the cone, u_n = 0 unless open, u_t = 0 when
    // sticking, and a slip opposes u_t.
    const double u_n = a(0, 0) * prepared_n + a(0, 1) * prepared_t + b_n;
    const double u_t = a(1, 0) * prepared_n + a(1, 1) * prepared_t + b_t;
    const double scale = std::hypot(b_n, b_t);
    EXPECT_GE(prepared_n, 0.0) << trial;
    EXPECT_LE(std::abs(prepared_t), mu * prepared_n * (1.0 + 1e-12) + 1e-15) << trial;
    if (c == Case::kOpen) {
      EXPECT_GE(u_n, 0.0) << trial;
    } else {
      EXPECT_LE(std::abs(u_n), 1e-12 * scale) << trial;
    }
    if (c == Case::kStick) {
      EXPECT_LE(std::abs(u_t), 1e-12 * scale) << trial;
    }
    if (c == Case::kSlipPositive) {
      EXPECT_GE(u_t, -1e-12 * scale) << trial;
    }
    if (c == Case::kSlipNegative) {
      EXPECT_LE(u_t, 1e-12 * scale) << trial;
    }
  }
  // Every case was met, many times over.
  for (int c = 0; c < 4; ++c) EXPECT_GT(counts[c], 1000) << "case " << c;
}

TEST(PreparedPlanarContact, ASingularBlockFallsBackAsTheUnpreparedOneDoes) {
  // Rank one: no stick solve; the slip or Newton cases answer, as without preparation.
  LocalMatrix a(2, 2);
  a << 1.0, 1.0, 1.0, 1.0;
  for (const double b_t : {-0.3, 0.0, 0.4}) {
    double direct_n = 0.0, direct_t = 0.0, prepared_n = 0.0, prepared_t = 0.0;
    const bool direct_exact = solve_single_contact_planar(a, -1.0, b_t, 0.5, direct_n, direct_t);
    const bool prepared_exact = solve_prepared_planar_contact(prepare_planar_contact(a, 0.5), -1.0,
                                                              b_t, prepared_n, prepared_t);
    EXPECT_EQ(prepared_exact, direct_exact) << b_t;
    EXPECT_NEAR(prepared_n, direct_n, 1e-12) << b_t;
    EXPECT_NEAR(prepared_t, direct_t, 1e-12) << b_t;
    EXPECT_GT(prepared_n, 0.0) << b_t;
  }
}

TEST(PreparedPlanarContact, AnUnsymmetricBlockSolvesAsUnpreparedEvenInTheNewtonFallback) {
  // The prepared record keeps W_ii for the Newton fallback; an unsymmetric block (a general
  // local matrix) tells its rows from its columns. Blocks with A_tt ≤ 0 leave some contacts to
  // the fallback, whose answer must still be the unprepared one.
  std::mt19937 random(20261130);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    LocalMatrix a(2, 2);
    a << 0.5 + std::abs(entry(random)), entry(random), entry(random), entry(random);
    const double mu = 0.8, b_n = -std::abs(entry(random)) - 0.1, b_t = entry(random);
    double direct_n = 0.0, direct_t = 0.0, prepared_n = 0.0, prepared_t = 0.0;
    const bool direct_exact = solve_single_contact_planar(a, b_n, b_t, mu, direct_n, direct_t);
    const bool prepared_exact = solve_prepared_planar_contact(prepare_planar_contact(a, mu), b_n,
                                                              b_t, prepared_n, prepared_t);
    ASSERT_EQ(prepared_exact, direct_exact) << trial;
    const double size = std::abs(direct_n) + std::abs(direct_t) + 1e-300;
    ASSERT_LE(std::abs(prepared_n - direct_n), 1e-10 * size) << trial;
    ASSERT_LE(std::abs(prepared_t - direct_t), 1e-10 * size) << trial;
  }
}

}  // namespace
}  // namespace impactbench::solvers
