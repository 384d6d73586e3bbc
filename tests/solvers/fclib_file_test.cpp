// FCLIB files: the five collection problems load (global ones reduced to W = Hᵀ M⁻¹ H), are
// solved to the FCLIB residual by our solvers (measured by the test's own formula); local
// problems round-trip through write/read; bad files are rejected by name.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/fclib_file.hpp"
#include "tests/support/solvers/independent_friction_residual.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::solvers {
namespace {

const std::filesystem::path kFclibDir = IMPACTBENCH_FCLIB_DIR;

struct CollectionFile {
  const char* name;
  int contacts;
  bool global;
  bool symmetric;  ///< Capsules stores a W with a ~2 % asymmetric pair (806, 805): data, not us
};

// spheres-in-a-box has a rank-deficient W (256 contacts × 3 rows on 98 spheres × 6 dofs): nsn
// reaches 1e-10 there in about 30 steps thanks to its regularised Newton direction and
// nonmonotone line search (semismooth_newton.cpp); nsgs alone stalls near 5e-6.
const CollectionFile kCollection[] = {
    {"Box_Stacks-i0122-82-5.hdf5", 82, true, true},
    {"Capsules-i125-1213.hdf5", 286, false, false},
    {"LMGC_100_PR_PerioBox-i00361-60-03000.hdf5", 60, false, true},
    {"Spheres-i099-356-679.hdf5", 356, true, true},
    {"spheres-in-a-box-98-i10000-256-10.hdf5", 256, true, true},
};

std::filesystem::path scratch_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("impactbench_fclib_test_" +
          std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name);
}

class FclibCollection : public ::testing::TestWithParam<CollectionFile> {};

TEST_P(FclibCollection, LoadsSolvesAndMatchesTheReference) {
  const CollectionFile& file = GetParam();
  const FclibProblem loaded = read_fclib_file(kFclibDir / file.name);
  const FrictionProblem& problem = loaded.problem;
  ASSERT_EQ(problem.dimension, 3);
  ASSERT_EQ(problem.num_contacts(), file.contacts);
  ASSERT_EQ(loaded.from_global, file.global);
  ASSERT_TRUE(problem.is_sparse);
  // The files store the whole W (both triangles, not one): check symmetry where the data is
  // symmetric, and that every normal diagonal entry is positive.
  const Eigen::SparseMatrix<double> w = problem.sparse_W;
  const Eigen::SparseMatrix<double> w_transpose = w.transpose();
  const double asymmetry = (w - w_transpose).norm() / w.norm();
  if (file.symmetric) {
    EXPECT_LE(asymmetry, 1e-12);
  } else {
    std::printf("%-45s stores a non-symmetric W: |W - W'| / |W| = %.2e\n", file.name, asymmetry);
  }
  for (int i = 0; i < problem.num_contacts(); ++i) ASSERT_GT(w.coeff(3 * i, 3 * i), 0.0);

  // Our solvers, cheapest first, until one reaches the FCLIB residual 1e-8.
  double best = 1.0;
  for (const auto& [name, budget] :
       {std::pair{"nsn", 300}, std::pair{"nsgs", 3000}, std::pair{"prox-gs", 3000}}) {
    SolverOptions options;
    options.tolerance = 1e-8;
    options.max_iterations = budget;
    const SolverResult result = solve_friction(problem, name, options);
    std::printf("%-45s %-8s residual %.3e iterations %5d %s\n", file.name, name, result.residual,
                result.iterations, std::string(to_string(result.status)).c_str());
    // Measured again by the test's own formula, not the solvers' residual code.
    const double independent =
        test_support::independent_friction_residual(problem, result.solution);
    EXPECT_NEAR(
        independent, result.residual,
        test_support::residual_allowance_for_velocity(problem, result.solution, result.velocity));
    best = std::min(best, independent);
    if (best <= 1e-8) break;
  }
  EXPECT_LE(best, 1e-8);

  // No file of the collection carries a reference to compare with: the global files' /solution
  // holds r = 0, v = 0 (placeholders), the local ones none that libfclib reads. A file with a
  // real reference would need the comparison (ours at least as good): fail then, so it is added.
  if (loaded.reference_r) {
    EXPECT_EQ(loaded.reference_r->lpNorm<Eigen::Infinity>(), 0.0)
        << "a real reference solution: compare ours with it";
  }
}

INSTANTIATE_TEST_SUITE_P(Files, FclibCollection, ::testing::ValuesIn(kCollection),
                         [](const auto& param_info) {
                           std::string name = param_info.param.name;
                           name = name.substr(0, name.find('-'));
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

TEST(FclibReduction, HandComputedGlobalProblem) {
  // Two dofs, one planar contact: M = diag(2, 4), H = [[1, 0], [1, 2]] (columns: n, t),
  // f = (2, 4), w = (0.5, 0). M⁻¹H = [[0.5, 0], [0.25, 0.5]];
  // W = Hᵀ M⁻¹ H = [[0.75, 0.5], [0.5, 1]], q = Hᵀ M⁻¹ f + w = Hᵀ (1, 1) + w = (2.5, 2).
  Eigen::SparseMatrix<double> m(2, 2);
  m.insert(0, 0) = 2.0;
  m.insert(1, 1) = 4.0;
  Eigen::SparseMatrix<double> h(2, 2);
  h.insert(0, 0) = 1.0;
  h.insert(1, 0) = 1.0;
  h.insert(1, 1) = 2.0;
  const FrictionProblem p =
      reduce_global_problem(2, m, h, Eigen::Vector2d(2.0, 4.0), Eigen::Vector2d(0.5, 0.0),
                            Eigen::VectorXd::Constant(1, 0.3));
  Eigen::Matrix2d expected;
  expected << 0.75, 0.5, 0.5, 1.0;
  EXPECT_LT((Eigen::MatrixXd(p.sparse_W) - expected).norm(), 1e-15);
  EXPECT_LT((p.q - Eigen::Vector2d(2.5, 2.0)).norm(), 1e-15);

  Eigen::SparseMatrix<double> indefinite = m;
  indefinite.coeffRef(1, 1) = -1.0;
  EXPECT_THROW(reduce_global_problem(2, indefinite, h, Eigen::Vector2d(2.0, 4.0),
                                     Eigen::Vector2d(0.5, 0.0), Eigen::VectorXd::Constant(1, 0.3)),
               std::runtime_error);
}

// The sparse reduction against a dense M⁻¹ on the two smaller global files.
TEST(FclibReduction, SparseReductionMatchesDenseInverse) {
  for (const char* name :
       {"Box_Stacks-i0122-82-5.hdf5", "spheres-in-a-box-98-i10000-256-10.hdf5"}) {
    SCOPED_TRACE(name);
    const FclibProblem loaded = read_fclib_file(kFclibDir / name);
    ASSERT_TRUE(loaded.from_global);
    const GlobalFclibProblem global = read_fclib_global_matrices(kFclibDir / name);
    const Eigen::MatrixXd m_inverse = Eigen::MatrixXd(global.M).inverse();
    const Eigen::MatrixXd h = global.H;
    const Eigen::MatrixXd w = h.transpose() * m_inverse * h;
    const Eigen::VectorXd q = h.transpose() * m_inverse * global.f + global.w;
    EXPECT_LE((Eigen::MatrixXd(loaded.problem.sparse_W) - w).norm(), 1e-10 * w.norm());
    EXPECT_LE((loaded.problem.q - q).norm(), 1e-10 * std::max(1.0, q.norm()));
  }
}

TEST(FclibWrite, LocalProblemRoundTrips) {
  for (const int dimension : {2, 3}) {
    const FrictionProblem original = random_friction_problem({12, 20, dimension, false, 4});
    const std::filesystem::path path = scratch_file("roundtrip.hdf5");
    write_fclib_local(original, path, "round trip");
    write_fclib_local(original, path, "round trip");  // replacing an existing file works too
    const FclibProblem read = read_fclib_file(path);
    std::filesystem::remove(path);
    EXPECT_EQ(read.problem.dimension, dimension);
    EXPECT_EQ(read.title, "round trip");
    EXPECT_FALSE(read.reference_r.has_value());
    EXPECT_EQ((Eigen::MatrixXd(read.problem.sparse_W) - original.dense_W).norm(), 0.0);
    EXPECT_EQ(read.problem.q, original.q);
    EXPECT_EQ(read.problem.mu, original.mu);
    for (const auto& entry : std::filesystem::directory_iterator(path.parent_path())) {
      EXPECT_EQ(entry.path().string().find(path.string() + ".tmp"), std::string::npos);
    }
  }
}

// A problem kept in its factors (sparse H and A, or factor blocks as a time stepper gives it) is
// written with W = H A formed: the file reads back as formed_delassus of it, entry for entry.
TEST(FclibWrite, FactoredProblemIsWrittenWithItsDelassusFormed) {
  for (const int dimension : {2, 3}) {
    for (const bool blocks : {false, true}) {
      RandomFrictionSpec spec{12, 20, dimension, false, 7};
      spec.factored = true;
      spec.factor_blocks = blocks;
      const FrictionProblem original = random_friction_problem(spec);
      ASSERT_TRUE(original.is_factored);
      const std::filesystem::path path = scratch_file("factored.hdf5");
      write_fclib_local(original, path, "factored");
      const FclibProblem read = read_fclib_file(path);
      std::filesystem::remove(path);
      const Eigen::MatrixXd formed = Eigen::MatrixXd(formed_delassus(original).sparse_W);
      ASSERT_EQ(read.problem.size(), original.size()) << dimension << " " << blocks;
      EXPECT_GT(formed.norm(), 0.0);
      EXPECT_EQ((Eigen::MatrixXd(read.problem.sparse_W) - formed).norm(), 0.0)
          << dimension << " " << blocks;
      EXPECT_EQ(read.problem.q, original.q);
      EXPECT_EQ(read.problem.mu, original.mu);
    }
  }
}

void expect_rejected(const std::filesystem::path& path, const std::string& reason) {
  try {
    read_fclib_file(path);
    ADD_FAILURE() << "accepted " << path;
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
  }
}

TEST(FclibBadInput, MissingFileIsNamed) {
  expect_rejected(kFclibDir / "no-such-problem.hdf5", "does not exist");
}

TEST(FclibBadInput, TextFileIsNotHdf5) {
  const std::filesystem::path path = scratch_file("text.hdf5");
  std::ofstream(path) << "not an HDF5 file\n";
  expect_rejected(path, "is not an HDF5 file");
  std::filesystem::remove(path);
}

TEST(FclibBadInput, TruncatedFileIsRejected) {
  const std::filesystem::path source = kFclibDir / "LMGC_100_PR_PerioBox-i00361-60-03000.hdf5";
  const std::filesystem::path path = scratch_file("truncated.hdf5");
  std::filesystem::copy_file(source, path, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::permissions(path, std::filesystem::perms::owner_write,
                               std::filesystem::perm_options::add);
  std::filesystem::resize_file(path, 4096);
  EXPECT_THROW(read_fclib_file(path), std::runtime_error);
  std::filesystem::remove(path);
}

TEST(FclibBadInput, WriteRejectsInconsistentSizes) {
  FrictionProblem problem = random_friction_problem({3, 5, 3, false, 1});
  problem.q.conservativeResize(7);
  EXPECT_THROW(write_fclib_local(problem, scratch_file("bad.hdf5")), std::runtime_error);
}

}  // namespace
}  // namespace impactbench::solvers
