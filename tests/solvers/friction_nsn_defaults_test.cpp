// nsn with its registry defaults (tolerance 1e-10, 200 Newton steps) on every FCLIB problem of
// the test collection: the default iteration limit must be enough (a limit that stops a
// solver on its way, as the monotone line search's slow phase did near it on
// spheres-in-a-box, 142 steps, reports max-iterations to users who took the defaults). The
// answer is checked by the test's own residual formula.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/fclib_file.hpp"
#include "tests/support/solvers/independent_friction_residual.hpp"

namespace impactbench::solvers {
namespace {

TEST(FrictionNsnDefaults, SolvesEveryCollectionFileWithinItsDefaultLimit) {
  const SolverInfo* nsn = nullptr;
  for (const SolverInfo& info : friction_solvers())
    if (info.name == "nsn") nsn = &info;
  ASSERT_NE(nsn, nullptr);
  for (const char* name : {"Box_Stacks-i0122-82-5.hdf5", "Capsules-i125-1213.hdf5",
                           "LMGC_100_PR_PerioBox-i00361-60-03000.hdf5", "Spheres-i099-356-679.hdf5",
                           "spheres-in-a-box-98-i10000-256-10.hdf5"}) {
    SCOPED_TRACE(name);
    const FclibProblem file = read_fclib_file(std::filesystem::path(IMPACTBENCH_FCLIB_DIR) / name);
    SolverOptions options;
    options.tolerance = nsn->default_tolerance;
    options.max_iterations = nsn->default_max_iterations;
    const SolverResult result = solve_friction(file.problem, "nsn", options);
    EXPECT_EQ(result.status, SolverStatus::kConverged) << result.message;
    EXPECT_LE(test_support::independent_friction_residual(file.problem, result.solution),
              nsn->default_tolerance * 1.0000001);
  }
}

}  // namespace
}  // namespace impactbench::solvers
