// WarmStart and VectorView read a VectorXd's or a CapacityVector's values where they are,
// without a copy: a solve warm-started from a kept answer, or handed one as a read-only
// argument, reads that answer's storage.
#include <cstddef>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "solvers/common/capacity_vector.hpp"
#include "solvers/common/warm_start.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

const double* data_of(VectorView view) {
  return view.data();
}

TEST(VectorView, ReadsAVectorXdOrACapacityVectorWhereItIs) {
  const Eigen::VectorXd plain = Eigen::VectorXd::LinSpaced(7, -1.0, 2.0);
  CapacityVector kept(20);
  kept = plain.head(5);
  EXPECT_EQ(data_of(plain), plain.data());
  EXPECT_EQ(data_of(kept), kept.data());
  const VectorView view = kept;
  EXPECT_EQ(view.size(), 5);
  EXPECT_EQ(view, plain.head(5));
}

TEST(WarmStart, NoneFromNullptrAndAViewOfTheVectorOtherwise) {
  const WarmStart none = nullptr;
  EXPECT_FALSE(none.given());
  EXPECT_TRUE(none == nullptr);
  EXPECT_FALSE(WarmStart().given());
  EXPECT_FALSE(WarmStart(static_cast<const Eigen::VectorXd*>(nullptr)).given());
  EXPECT_FALSE(WarmStart(static_cast<const CapacityVector*>(nullptr)).given());

  const Eigen::VectorXd plain = Eigen::VectorXd::LinSpaced(6, 0.0, 1.0);
  const WarmStart from_plain = &plain;
  ASSERT_TRUE(from_plain.given());
  EXPECT_TRUE(from_plain != nullptr);
  EXPECT_EQ(from_plain->data(), plain.data());
  EXPECT_EQ(from_plain->size(), 6);

  CapacityVector kept(9);
  kept = plain.tail(4);
  const WarmStart from_kept = &kept;
  ASSERT_TRUE(from_kept.given());
  EXPECT_EQ((*from_kept).data(), kept.data());
  EXPECT_EQ(*from_kept, plain.tail(4));
}

// The stepper's way: each solve warm-started from the kept answer of the solve before. A
// warm start that solves the problem ends at the driver's entry check with that answer.
TEST(WarmStart, FromAKeptAnswerStartsTheSolveThere) {
  const FrictionProblem problem = random_friction_problem({12, 24, 2, false, 3, true, true});
  const FrictionSolver solver("nsgs");
  const SolverResult first = solver.solve(problem);
  ASSERT_TRUE(first.converged()) << first.message;
  const SolverResult again = solver.solve(problem, {}, &first.solution);
  ASSERT_TRUE(again.converged()) << again.message;
  EXPECT_EQ(again.iterations, 0);
  EXPECT_EQ(again.solution, first.solution);
  // A warm start of the wrong size is refused, as a VectorXd's was.
  CapacityVector short_start(4);
  short_start.setZero();
  const SolverResult refused = solver.solve(problem, {}, &short_start);
  EXPECT_EQ(refused.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(refused.message.find("warm start has 4 entries"), std::string::npos) << refused.message;
}

}  // namespace
}  // namespace impactbench::solvers
