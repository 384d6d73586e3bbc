// Root location on a step's dense output (root_search.hpp): the earliest downward crossing of
// a vector of guards, against closed-form roots, with CVODE's contract (only downward
// crossings count, a zero at the step's end is a root, the root reported is the bracket's upper
// end within the tolerance).
#include <cmath>
#include <functional>
#include <stdexcept>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/root_search.hpp"

namespace impactbench::engines::event_driven {
namespace {

using Guards = std::function<void(double, Eigen::Ref<Eigen::VectorXd>)>;

Eigen::VectorXd values_at(const Guards& g, double t, Eigen::Index n) {
  Eigen::VectorXd out(n);
  g(t, out);
  return out;
}

RootBracket locate(const Guards& g, double t_lo, double t_hi, Eigen::Index n, double tol) {
  return locate_earliest_root(g, t_lo, values_at(g, t_lo, n), t_hi, values_at(g, t_hi, n), tol);
}

TEST(EventRootSearch, FindsTheRootOfAFallingParabolaWithinTheTolerance) {
  // A ball's gap in free flight: 1 − t² crosses at t = 1.
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) { out[0] = 1.0 - t * t; };
  const double tol = 1e-12;
  const RootBracket root = locate(g, 0.0, 10.0, 1, tol);
  // The bracket closes to the tolerance unless a point lands on the zero itself.
  EXPECT_TRUE(root.t_hi - root.t_lo <= tol || root.g_hi[0] == 0.0);
  EXPECT_GE(root.t_hi, 1.0);
  EXPECT_LE(root.t_hi, 1.0 + tol);
  EXPECT_EQ(root.found, std::vector<int>{-1});
  EXPECT_GT(root.g_lo[0], 0.0);
  EXPECT_LE(root.g_hi[0], 0.0);
}

TEST(EventRootSearch, FindsTheRootOfANonPolynomialGuard) {
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) { out[0] = std::cos(t); };
  const double tol = 1e-12;
  const RootBracket root = locate(g, 0.0, 3.0, 1, tol);
  EXPECT_NEAR(root.t_hi, M_PI / 2, tol);
  EXPECT_EQ(root.found, std::vector<int>{-1});
}

TEST(EventRootSearch, ReportsOnlyTheEarliestOfTwoCrossings) {
  // Roots at ln 2 ≈ 0.693 and 0.7.
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) {
    out[0] = 0.7 - t;
    out[1] = std::exp(-t) - 0.5;
  };
  const double tol = 1e-12;
  const RootBracket root = locate(g, 0.0, 2.0, 2, tol);
  EXPECT_NEAR(root.t_hi, std::log(2.0), tol);
  EXPECT_EQ(root.found, (std::vector<int>{0, -1}));
}

TEST(EventRootSearch, IgnoresUpwardCrossings) {
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) {
    out[0] = t - 0.5;  // crosses upwards at 0.5
    out[1] = 0.8 - t;
  };
  const RootBracket root = locate(g, 0.0, 1.0, 2, 1e-12);
  EXPECT_NEAR(root.t_hi, 0.8, 1e-12);
  EXPECT_EQ(root.found, (std::vector<int>{0, -1}));
}

TEST(EventRootSearch, AZeroAtTheEndOfTheStepIsTheRoot) {
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) { out[0] = 1.0 - t; };
  const RootBracket root = locate(g, 0.0, 1.0, 1, 1e-12);
  EXPECT_EQ(root.t_hi, 1.0);
  EXPECT_EQ(root.found, std::vector<int>{-1});
}

TEST(EventRootSearch, RefusesAnIntervalWithoutACrossing) {
  const Guards g = [](double t, Eigen::Ref<Eigen::VectorXd> out) { out[0] = 1.0 + t; };
  EXPECT_THROW(locate(g, 0.0, 1.0, 1, 1e-12), std::logic_error);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
