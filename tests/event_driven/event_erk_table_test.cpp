// The Butcher tables our own Runge–Kutta driver (method = own_erk) reads from ARKODE, and
// Dormand–Prince's continuous extension, held to the order conditions of their stated orders:
// consistent nodes (c_i = Σ_j a_ij), the quadrature conditions Σ b_i c_i^(k−1) = 1/k up to the
// method's order and Σ d_i c_i^(k−1) = 1/k up to the embedding's, and the four tree conditions of
// order 3 and 4 for both. A table read wrong (a transposed a, b and d swapped, a stage missing)
// breaks at least one.
#include <cfloat>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/erk_table.hpp"

namespace impactbench::engines::event_driven {
namespace {

struct Expected {
  ErkPair pair;
  const char* name;
  int order, embedding_order;
  bool first_same_as_last;
};

class ErkTable : public testing::TestWithParam<Expected> {};

// The round-off of a sum of n terms with these magnitudes, each term itself a product of a few
// rounded coefficients: 4 n ε times the sum of their magnitudes.
double round_off(const Eigen::VectorXd& magnitudes) {
  return 4.0 * static_cast<double>(magnitudes.size()) * DBL_EPSILON * magnitudes.sum();
}

// Σ_i w_i x_i against its exact value, to the sum's round-off.
void expect_sum(const Eigen::VectorXd& w, const Eigen::VectorXd& x, double exact,
                const std::string& what) {
  const Eigen::VectorXd terms = w.cwiseProduct(x);
  EXPECT_NEAR(terms.sum(), exact, round_off(terms.cwiseAbs())) << what;
}

// The order conditions of the weights w (b or d, or a dense output's at θ) up to order p: for a
// tree of order ρ and density γ, Σ w_i Φ_i = θ^ρ / γ (θ = 1: the step's end).
void expect_order_conditions(const ButcherPair& t, const Eigen::VectorXd& w, int p,
                             const std::string& which, double theta = 1.0) {
  const Eigen::VectorXd c = t.c;
  const Eigen::VectorXd ac = t.a * c;
  for (int k = 1; k <= p; ++k)
    expect_sum(w, c.array().pow(k - 1).matrix(), std::pow(theta, k) / k,
               which + " c^" + std::to_string(k - 1));
  if (p >= 3) expect_sum(w, ac, std::pow(theta, 3) / 6.0, which + " A c");
  if (p >= 4) {
    expect_sum(w, c.cwiseProduct(ac), std::pow(theta, 4) / 8.0, which + " C A c");
    expect_sum(w, t.a * c.cwiseProduct(c), std::pow(theta, 4) / 12.0, which + " A c²");
    expect_sum(w, t.a * ac, std::pow(theta, 4) / 24.0, which + " A A c");
  }
}

TEST_P(ErkTable, SatisfiesTheOrderConditionsOfItsStatedOrders) {
  const Expected& expected = GetParam();
  const ButcherPair t = load_butcher_pair(expected.pair);
  EXPECT_EQ(t.order, expected.order);
  EXPECT_EQ(t.embedding_order, expected.embedding_order);
  EXPECT_EQ(t.first_same_as_last, expected.first_same_as_last);
  ASSERT_EQ(t.a.rows(), t.stages());
  for (int i = 0; i < t.stages(); ++i) {
    const Eigen::VectorXd row = t.a.row(i).transpose();
    EXPECT_NEAR(row.sum(), t.c[i], round_off(row.cwiseAbs())) << "row " << i;
    for (int j = i; j < t.stages(); ++j) {
      EXPECT_EQ(t.a(i, j), 0.0) << "explicit: a(" << i << ", " << j << ")";
    }
  }
  expect_order_conditions(t, t.b, t.order, "b");
  expect_order_conditions(t, t.d, t.embedding_order, "d");
}

// The weights w(θ) of the dense output y(θ) = y₀ + h Σ_i w_i(θ) k_i of a pair whose first is
// the same as its last (ẏ₁ = k_s): the cubic Hermite interpolant through y₀,
// y₁ = y₀ + h Σ b_i k_i and the slopes k₁ and k_s,
// θ b + θ (1 − θ) (δ₁ − b) + θ² (1 − θ) (2 b − δ₁ − δ_s), plus the quartic correction
// θ² (1 − θ)² e. (The driver evaluates the same polynomial nested, from y₁ − y₀;
// event_flow_session_test.cpp checks it on a quartic.)
Eigen::VectorXd first_same_as_last_dense_weights(const ButcherPair& t, const Eigen::VectorXd& e,
                                                 double theta) {
  const int s = t.stages();
  Eigen::VectorXd first = Eigen::VectorXd::Zero(s), last = Eigen::VectorXd::Zero(s);
  first[0] = 1.0;
  last[s - 1] = 1.0;
  const double rest = 1.0 - theta;
  Eigen::VectorXd w = theta * t.b + theta * rest * (first - t.b) +
                      theta * theta * rest * (2.0 * t.b - first - last);
  if (e.size() == s) w += theta * theta * rest * rest * e;
  return w;
}

// Dormand–Prince's continuous extension is of order 4 at every θ: its weights satisfy the
// conditions of order 4 at θ. The cubic Hermite interpolant alone does not (order 3), so the
// quartic correction is needed and read right.
TEST(ErkTableDenseOutput, DormandPrinceIsOfOrderFourAtEveryTheta) {
  const ButcherPair t = load_butcher_pair(ErkPair::kDormandPrince54);
  ASSERT_TRUE(t.first_same_as_last);
  for (const double theta : {0.1, 0.25, 0.5, 0.73, 0.9, 1.0})
    expect_order_conditions(t, first_same_as_last_dense_weights(t, t.quartic_correction, theta), 4,
                            "θ = " + std::to_string(theta), theta);
  // Without the correction the order-4 quadrature condition fails at θ = 1/2 by far more than
  // round-off.
  const Eigen::VectorXd hermite = first_same_as_last_dense_weights(t, Eigen::VectorXd(), 0.5);
  EXPECT_GT(std::abs(hermite.dot(t.c.array().pow(3).matrix()) - std::pow(0.5, 4) / 4.0), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(
    Pairs, ErkTable,
    testing::Values(Expected{ErkPair::kDormandPrince54, "DormandPrince54", 5, 4, true},
                    Expected{ErkPair::kVerner65, "Verner65", 6, 5, false},
                    Expected{ErkPair::kFehlberg87, "Fehlberg87", 8, 7, false}),
    [](const testing::TestParamInfo<Expected>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace impactbench::engines::event_driven
