// `impactbench solve` for real problems, through the program as a user runs it: the solution
// file (checked against the problem read independently), solver settings by --option, warm
// starts, the time limit and the progress line, and every bad input refused in one line with
// no file left behind.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/io/fclib_file.hpp"
#include "solvers/io/lcp_text_file.hpp"
#include "tests/support/engines/cli_runner.hpp"
#include "tests/support/solvers/independent_friction_residual.hpp"

namespace {

namespace fs = std::filesystem;
using Outcome = impactbench::test_support::CliOutcome;

const std::string kChain = IMPACTBENCH_TEST_DATA_DIR "/lcp/chain_5_sparse.lcp";
const std::string kBoxStack = IMPACTBENCH_FCLIB_DIR "/Box_Stacks-i0122-82-5.hdf5";

/// The numeric rows of a CSV with a header (every field a number).
std::vector<std::vector<double>> csv_rows(const fs::path& path, std::string* header) {
  std::ifstream in(path);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

/// The number after `label` in the program's report (NaN when absent).
double reported(const std::string& out, const std::string& label) {
  const auto at = out.find("\n" + label);
  if (at == std::string::npos) return std::nan("");
  return std::stod(out.substr(at + 1 + label.size()));
}

class CliSolve : public ::testing::Test {
 protected:
  Outcome run(const std::string& arguments, int seconds = 60) const {
    return impactbench::test_support::run_program(IMPACTBENCH_CLI, arguments, capture_.path(), "",
                                                  directory_.path(), seconds);
  }
  fs::path file(const std::string& name) const { return directory_.path() / name; }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name)) << text;
  }
  std::size_t file_count() const {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory_.path())) ++count;
    return count;
  }
  /// One line on stderr naming `message`, the exit code, and no new file.
  void expect_failure(const Outcome& outcome, int exit_code, const std::string& message,
                      std::size_t files_before) const {
    EXPECT_EQ(outcome.exit_code, exit_code) << outcome.err;
    ASSERT_FALSE(outcome.err.empty());
    EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
    EXPECT_NE(outcome.err.find(message), std::string::npos) << outcome.err;
    EXPECT_EQ(file_count(), files_before) << "a failed solve left a file";
  }

  impactbench::test_support::TemporaryDirectory directory_{"cli_solve"};
  impactbench::test_support::TemporaryDirectory capture_{"cli_solve_capture"};
};

// z and w = Mz + q of the solution file, checked on the problem read here: w matches Mz + q
// and min(z, w) vanishes; a warm start from it converges at once.
TEST_F(CliSolve, LcpSolutionFileHoldsAComplementaryPairAndWarmStarts) {
  const Outcome solved = run("solve '" + kChain + "' --solver pgs --tol 1e-12 --solution z.csv");
  ASSERT_EQ(solved.exit_code, 0) << solved.err << solved.out;
  std::string header;
  const auto rows = csv_rows(file("z.csv"), &header);
  EXPECT_EQ(header, "i,z,w");
  const auto problem = impactbench::solvers::io::read_lcp_file(kChain);
  ASSERT_EQ(rows.size(), 5u);
  Eigen::VectorXd z(5), w(5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(rows[i][0], i);
    z(i) = rows[i][1];
    w(i) = rows[i][2];
  }
  const Eigen::VectorXd mz_q = Eigen::MatrixXd(problem.sparse_M) * z + problem.q;
  EXPECT_LT((w - mz_q).lpNorm<Eigen::Infinity>(), 1e-15);
  EXPECT_LT(z.cwiseMin(mz_q).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT((z - Eigen::VectorXd::Ones(5)).lpNorm<Eigen::Infinity>(), 1e-11);  // z = 1

  const Outcome warm = run("solve '" + kChain + "' --solver pgs --tol 1e-12 --warm-start z.csv");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_GT(reported(solved.out, "iterations "), 10.0);
  EXPECT_LE(reported(warm.out, "iterations "), 1.0) << warm.out;
}

// r and u of a friction problem: the FCLIB residual of the file's r, recomputed here, is below
// the tolerance, and u = W r + q.
TEST_F(CliSolve, FrictionSolutionFileHoldsRAndU) {
  const Outcome solved = run("solve '" + kBoxStack + "' --solver nsgs --tol 1e-8 --solution r.csv");
  ASSERT_EQ(solved.exit_code, 0) << solved.err << solved.out;
  std::string header;
  const auto rows = csv_rows(file("r.csv"), &header);
  EXPECT_EQ(header, "contact,r_n,r_t1,r_t2,u_n,u_t1,u_t2");
  const auto fclib = impactbench::solvers::read_fclib_file(kBoxStack);
  const auto& problem = fclib.problem;
  ASSERT_EQ(static_cast<int>(rows.size()), problem.num_contacts());
  Eigen::VectorXd r(problem.size()), u(problem.size());
  for (int i = 0; i < problem.num_contacts(); ++i)
    for (int k = 0; k < 3; ++k) {
      r(3 * i + k) = rows[i][1 + k];
      u(3 * i + k) = rows[i][4 + k];
    }
  const Eigen::VectorXd w_r_q =
      (problem.is_sparse ? Eigen::MatrixXd(problem.sparse_W) : problem.dense_W) * r + problem.q;
  EXPECT_LT((u - w_r_q).lpNorm<Eigen::Infinity>(), 1e-12 * (1.0 + w_r_q.lpNorm<Eigen::Infinity>()));
  EXPECT_LT(impactbench::test_support::independent_friction_residual(problem, r), 1e-8);

  const Outcome warm = run("solve '" + kBoxStack + "' --solver nsgs --tol 1e-8 --warm-start r.csv");
  ASSERT_EQ(warm.exit_code, 0) << warm.err;
  EXPECT_EQ(reported(warm.out, "iterations "), 0.0) << warm.out;  // already solved
}

// psor's relaxation reaches the solver: ω = 1 is pgs (same sweeps), ω = 1.5 is not; both
// converge (the residual is checked by the driver).
TEST_F(CliSolve, OptionReachesPsorRelaxation) {
  const auto iterations = [&](const std::string& arguments) {
    const Outcome outcome = run("solve '" + kChain + "' --tol 1e-12 " + arguments);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err << outcome.out;
    return reported(outcome.out, "iterations ");
  };
  const double pgs = iterations("--solver pgs");
  EXPECT_EQ(iterations("--solver psor --option relaxation=1"), pgs);
  EXPECT_NE(iterations("--solver psor --option relaxation=1.5"), pgs);
}

// Friction settings: the facet count changes Lemke's faceted problem (more pivots), the
// proximal ω and ρ change the sweeps of prox-gs.
TEST_F(CliSolve, OptionReachesFrictionSolverSettings) {
  const auto iterations = [&](const std::string& arguments) {
    const Outcome outcome = run("solve '" + kBoxStack + "' " + arguments);
    return reported(outcome.out, "iterations ");
  };
  EXPECT_NE(iterations("--solver lemke --option cone_facets=4"),
            iterations("--solver lemke --option cone_facets=16"));
  const double plain = iterations("--solver prox-gs --tol 1e-6");
  EXPECT_NE(iterations("--solver prox-gs --tol 1e-6 --option omega=0.3"), plain);
  EXPECT_NE(iterations("--solver prox-gs --tol 1e-6 --option rho_scale=0.2"), plain);
}

// Lemke solves the faceted-cone LCP of a spatial problem exactly, which is not the problem as
// stated (the Coulomb disk): exit 3, one line saying so, and the faceted solution written.
TEST_F(CliSolve, AFacetedConeAnswerIsNotASolutionOfTheProblemAsStated) {
  const Outcome outcome = run("solve '" + kBoxStack + "' --solver lemke --solution s.csv");
  EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
  EXPECT_NE(outcome.out.find("status   converged-faceted-cone"), std::string::npos) << outcome.out;
  EXPECT_EQ(outcome.err.find('\n'), outcome.err.size() - 1) << outcome.err;
  EXPECT_NE(outcome.err.find("not the problem as stated: Coulomb residual"), std::string::npos)
      << outcome.err;
  EXPECT_GT(reported(outcome.out, "residual "), 1e-10);  // the Coulomb residual, above --tol
  EXPECT_EQ(file_count(), 1u);                           // s.csv: the faceted cone's solution
}

TEST_F(CliSolve, BadOptionsAreUsageErrorsListingTheValidKeys) {
  expect_failure(run("solve '" + kChain + "' --solver psor --option omega=1.5 --solution s.csv"), 2,
                 "not a setting of psor (it accepts relaxation (a number in (0, 2))", 0);
  expect_failure(run("solve '" + kChain + "' --solver psor --option relaxation=2"), 2,
                 "relaxation: must be in (0, 2), got '2'", 0);
  expect_failure(run("solve '" + kChain + "' --solver psor --option relaxation=nan"), 2,
                 "relaxation", 0);
  expect_failure(run("solve '" + kChain + "' --solver lemke --option relaxation=1"), 2,
                 "not a setting of lemke (it has none besides --tol and --max-iter)", 0);
  expect_failure(run("solve '" + kBoxStack + "' --solver nsgs --option cone_facets=8"), 2,
                 "not a setting of nsgs", 0);
  expect_failure(run("solve '" + kBoxStack + "' --solver lemke --option cone_facets=2"), 2,
                 "cone_facets", 0);
  expect_failure(run("solve '" + kBoxStack + "' --solver nsn --option rho_scale=0"), 2, "rho_scale",
                 0);
  expect_failure(run("solve '" + kChain + "' --solver psor --option relaxation"), 2,
                 "is not [ENGINE.]key=value", 0);
  expect_failure(run("solve '" + kChain + "' --solver pgs --time-limit 0"), 2,
                 "must be a finite number > 0", 0);
}

TEST_F(CliSolve, BadWarmStartsAreRefusedInOneLineWithNoSolutionWritten) {
  write("short.csv", "i,z,w\n0,1,0\n1,1,0\n");
  write("nan.csv", "i,z,w\n0,1,0\n1,nan,0\n2,1,0\n3,1,0\n4,1,0\n");
  write("text.csv", "i,z,w\n0,1,0\n1,1x,0\n2,1,0\n3,1,0\n4,1,0\n");
  write("columns.csv", "i,r_n\n0,1\n");
  write("long.csv", "i,z,w\n0,1,0\n1,1,0\n2,1,0\n3,1,0\n4,1,0\n5,1,0\n");
  write("empty.csv", "");
  const std::size_t files = file_count();
  const std::string solve = "solve '" + kChain + "' --solver pgs --solution out.csv --warm-start ";
  expect_failure(run(solve + "short.csv"), 1, "short.csv: 2 rows, the problem has 5 unknowns",
                 files);
  expect_failure(run(solve + "nan.csv"), 1, "nan.csv:3: z is not a finite number: 'nan'", files);
  expect_failure(run(solve + "text.csv"), 1, "text.csv:3: z is not a finite number: '1x'", files);
  expect_failure(run(solve + "columns.csv"), 1, "columns.csv:1: no column 'z'", files);
  expect_failure(run(solve + "long.csv"), 1, "long.csv:7: more rows than the problem's 5", files);
  expect_failure(run(solve + "empty.csv"), 1, "empty.csv:1: empty file", files);
  expect_failure(run(solve + "missing.csv"), 1, "missing.csv: no such file", files);
  // A friction problem wants r columns; an LCP solution is not one.
  write("z.csv", "i,z,w\n0,1,0\n");
  expect_failure(
      run("solve '" + kBoxStack + "' --solver nsgs --solution out.csv --warm-start z.csv"), 1,
      "z.csv:1: no column 'r_n'", files + 1);
  expect_failure(run("solve '" + kChain + "' --solver pgs --solution nodir/out.csv"), 1,
                 "directory nodir does not exist", files + 1);
}

// A solve that cannot finish (tolerance below rounding, no iteration limit to speak of) stops
// at the time limit, says so, exits 1 and writes no solution; --progress shows its progress.
TEST_F(CliSolve, TimeLimitStopsALongSolveWithProgress) {
  const Outcome outcome = run("solve '" + kChain +
                                  "' --solver psor --tol 1e-300 --max-iter 2000000000 "
                                  "--time-limit 2.5 --progress --solution s.csv",
                              30);
  EXPECT_EQ(outcome.exit_code, 1) << outcome.err << outcome.out;
  EXPECT_NE(outcome.out.find("status   stopped: time limit 2.5 s (process CPU) reached"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.err.find("solve: iteration "), std::string::npos) << outcome.err;
  EXPECT_EQ(file_count(), 0u);
  EXPECT_GE(reported(outcome.out, "time     "), 0.0);
}

}  // namespace
