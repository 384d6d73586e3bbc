// Plain-text LCP files: exact round trips, the example files' known solutions, and one precise
// "<path>:<line>: <what>" message per kind of malformed input.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "solvers/io/lcp_text_file.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tests/support/solvers/lcp_test_problems.hpp"

namespace impactbench::solvers {
namespace {

namespace fs = std::filesystem;

const fs::path kDataDir = fs::path(IMPACTBENCH_TEST_DATA_DIR) / "lcp";

class LcpTextFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           ("lcp_text_file_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write_text(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  // The message read_lcp_file gives for `text`, which must be rejected.
  std::string error_for(const std::string& text) const {
    const fs::path path = write_text("bad.lcp", text);
    try {
      io::read_lcp_file(path);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << text;
    return {};
  }
  std::string prefix(int line) const {
    return (dir_ / "bad.lcp").string() + ":" + std::to_string(line) + ": ";
  }

  fs::path dir_;
};

TEST_F(LcpTextFile, DenseRoundTripIsExact) {
  const LcpProblem p = lcp::random_nonsymmetric_pd_problem(7, 11);
  const fs::path path = dir_ / "dense.lcp";
  io::write_lcp_file(path, p);
  const LcpProblem back = io::read_lcp_file(path);
  ASSERT_FALSE(back.is_sparse);
  EXPECT_EQ(back.dense_M, p.dense_M);
  EXPECT_EQ(back.q, p.q);
}

TEST_F(LcpTextFile, SparseRoundTripIsExactAndOverwrites) {
  const LcpProblem p = lcp::random_sparse_contact_problem(40, 3);
  const fs::path path = write_text("sparse.lcp", "old content");
  io::write_lcp_file(path, p);
  const LcpProblem back = io::read_lcp_file(path);
  ASSERT_TRUE(back.is_sparse);
  EXPECT_EQ(back.sparse_M.nonZeros(), p.sparse_M.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(back.sparse_M), Eigen::MatrixXd(p.sparse_M));
  EXPECT_EQ(back.q, p.q);
  // Only the target remains: the temporary file was renamed, not left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(LcpTextFile, WriteFailureNamesThePathAndLeavesNothing) {
  const fs::path path = dir_ / "missing_dir" / "p.lcp";
  try {
    io::write_lcp_file(path, lcp::murty_problem(3));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "missing_dir"));
  LcpProblem nan = lcp::murty_problem(3);
  nan.q(0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(io::write_lcp_file(dir_ / "nan.lcp", nan), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir_ / "nan.lcp"));
}

// The committed examples: known solutions, and every applicable solver agrees with them.
TEST_F(LcpTextFile, ExampleFilesHaveTheirDocumentedSolutions) {
  struct Case {
    const char* file;
    Eigen::VectorXd z;
  };
  const Case cases[] = {
      {"two_by_two.lcp", Eigen::Vector2d(1.0 / 3.0, 1.0 / 3.0)},
      {"murty_4.lcp", Eigen::Vector4d(0, 0, 0, 1)},
      {"chain_5_sparse.lcp", Eigen::VectorXd::Ones(5)},
  };
  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 100000;
  for (const Case& c : cases) {
    const LcpProblem p = io::read_lcp_file(kDataDir / c.file);
    for (const SolverInfo& info : lcp_solvers()) {
      // Sweeps are only guaranteed to converge for symmetric positive definite M.
      if (info.iterative && info.name != "newton-fb" && std::string(c.file) == "murty_4.lcp") {
        continue;
      }
      SCOPED_TRACE(std::string(c.file) + " " + info.name);
      const SolverResult r = solve_lcp(p, info.name, options);
      ASSERT_TRUE(r.converged()) << r.message;
      EXPECT_LT((r.solution - c.z).cwiseAbs().maxCoeff(), 1e-10);
    }
  }
  const SolverResult ray = solve_lcp(io::read_lcp_file(kDataDir / "infeasible_2.lcp"), "lemke");
  EXPECT_EQ(ray.status, SolverStatus::kRayTermination);
}

TEST_F(LcpTextFile, MissingFileIsNamed) {
  try {
    io::read_lcp_file(dir_ / "nope.lcp");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("nope.lcp"), std::string::npos) << e.what();
  }
}

TEST_F(LcpTextFile, MalformedFilesAreRejectedWithPathAndLine) {
  EXPECT_EQ(error_for("# only a comment\nlcp 2 banded\n-1 -1\n"),
            prefix(2) + "expected header 'lcp <n> dense|sparse'");
  EXPECT_EQ(error_for("lcp zero dense\n"), prefix(1) + "size 'zero' is not a positive integer");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 -1 -1\n1 0\n0 1\n"),
            prefix(2) + "expected 2 entries of q, found 3");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 -1\n1 0\n\n0 1x\n"),
            prefix(5) + "M entry '1x' is not a number");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 nan\n1 0\n0 1\n"),
            prefix(2) + "q entry 'nan' is not finite");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 -1\n1 0\n0 inf\n"),
            prefix(4) + "M entry 'inf' is not finite");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 -1\n1 0 # one row only\n"),
            prefix(3) + "file ends after 1 rows of dense M, expected 2");
  EXPECT_EQ(error_for("lcp 2 dense\n-1 -1\n1 0\n0 1\n7\n"),
            prefix(5) + "unexpected text after the last row of M");
  EXPECT_EQ(error_for("lcp 2 sparse\n-1 -1\n0 0 1\n0 2 1\n"),
            prefix(4) + "column index 2 is out of range [0, 2)");
  EXPECT_EQ(error_for("lcp 2 sparse\n-1 -1\n0 0 1\n1 1\n"),
            prefix(4) + "expected 3 values 'i j value', found 2");
  EXPECT_EQ(error_for("lcp 2 sparse\n-1 -1\n0 0 1\n0 0 2\n"),
            prefix(4) + "entry (0, 0) appears twice");
  EXPECT_EQ(error_for("lcp 2 sparse\n"), prefix(1) + "file ends before the line of q");
  EXPECT_EQ(error_for(""),
            prefix(1) + "file ends before the header; expected header 'lcp <n> dense|sparse'");
}

}  // namespace
}  // namespace impactbench::solvers
