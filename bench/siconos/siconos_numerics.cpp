#include "siconos/siconos_numerics.hpp"

#include <cmath>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCore>

// Siconos Numerics' C headers (they declare extern "C" themselves).
#include "FrictionContactProblem.h"
#include "Friction_cst.h"
#include "LinearComplementarityProblem.h"
#include "NonSmoothDrivers.h"
#include "NumericsMatrix.h"
#include "SolverOptions.h"
#include "SparseBlockMatrix.h"

namespace impactbench::bench {
namespace {

struct MatrixDeleter {
  void operator()(NumericsMatrix* m) const { NM_free(m); }
};
struct OptionsDeleter {
  void operator()(SolverOptions* o) const { solver_options_delete(o); }
};
using MatrixPtr = std::unique_ptr<NumericsMatrix, MatrixDeleter>;
using OptionsPtr = std::unique_ptr<SolverOptions, OptionsDeleter>;

double cpu_seconds_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

/// Dense column-major copy (Siconos' NM_DENSE layout is Eigen's default one).
MatrixPtr dense_copy(const Eigen::MatrixXd& m) {
  MatrixPtr matrix(NM_create(NM_DENSE, static_cast<int>(m.rows()), static_cast<int>(m.cols())));
  Eigen::Map<Eigen::MatrixXd>(matrix->matrix0, m.rows(), m.cols()) = m;
  return matrix;
}

/// Sparse-block copy with d×d blocks, through a triplet/CSC matrix and SBM_from_csparse.
MatrixPtr sparse_block_copy(const Eigen::SparseMatrix<double>& m, int block) {
  const int n = static_cast<int>(m.rows());
  const MatrixPtr triplets(NM_create(NM_SPARSE, n, n));
  NM_triplet_alloc(triplets.get(), static_cast<CS_INT>(m.nonZeros()));
  CSparseMatrix* entries = NM_triplet(triplets.get());
  for (int col = 0; col < m.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, col); it; ++it) {
      CSparseMatrix_entry(entries, it.row(), col, it.value());
    }
  }
  SparseBlockStructuredMatrix* blocks = SBM_new();
  if (SBM_from_csparse(block, NM_csc(triplets.get()), blocks) != 0) {
    SBM_clear(blocks);
    throw std::runtime_error("Siconos SBM_from_csparse failed");
  }
  return MatrixPtr(NM_new_SBM(n, n, blocks));
}

/// Guards the copy: Siconos' W x must equal ours for a test vector (catches a transposed or
/// partial conversion, which would silently make the comparison meaningless).
void check_product(NumericsMatrix* copy, const Eigen::SparseMatrix<double>& m) {
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(m.cols(), 1.0, 2.0);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(m.rows());
  NM_gemv(1.0, copy, x.data(), 0.0, y.data());
  const Eigen::VectorXd expected = m * x;
  if (!((y - expected).norm() <= 1e-12 * (1.0 + expected.norm()))) {
    throw std::runtime_error("Siconos copy of W does not reproduce W x");
  }
}

OptionsPtr options_for(int solver_id, double tolerance, int max_iterations) {
  OptionsPtr options(solver_options_create(solver_id));
  if (!options)
    throw std::invalid_argument("unknown Siconos solver id " + std::to_string(solver_id));
  options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
  options->dparam[SICONOS_DPARAM_TOL] = tolerance;
  return options;
}

}  // namespace

std::string siconos_solver_name(int solver_id) {
  const char* name = solver_options_id_to_name(solver_id);
  return name != nullptr ? name : "unknown";
}

SiconosRun siconos_lcp(const solvers::LcpProblem& problem, int solver_id, double tolerance,
                       int max_iterations, int repeats) {
  const int n = problem.size();
  const MatrixPtr m = problem.is_sparse ? dense_copy(Eigen::MatrixXd(problem.sparse_M))
                                        : dense_copy(problem.dense_M);
  std::vector<double> q(problem.q.data(), problem.q.data() + n);
  LinearComplementarityProblem lcp{n, m.get(), q.data()};
  const OptionsPtr options = options_for(solver_id, tolerance, max_iterations);
  SiconosRun run;
  run.solution = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
  const std::clock_t start = std::clock();
  for (int call = 0; call < repeats; ++call) {
    run.solution.setZero();
    w.setZero();
    run.info = linearComplementarity_driver(&lcp, run.solution.data(), w.data(), options.get());
  }
  run.seconds = cpu_seconds_since(start) / repeats;
  run.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  run.own_error = options->dparam[SICONOS_DPARAM_RESIDU];
  return run;
}

SiconosRun siconos_fc3d(const solvers::FrictionProblem& problem, int solver_id, double tolerance,
                        int max_iterations, int repeats) {
  if (problem.dimension != 3) {
    throw std::invalid_argument("Siconos fc3d solves spatial problems only");
  }
  const Eigen::SparseMatrix<double> w =
      problem.is_sparse ? Eigen::SparseMatrix<double>(problem.sparse_W)
                        : Eigen::SparseMatrix<double>(problem.dense_W.sparseView());
  const MatrixPtr m = sparse_block_copy(w, 3);
  check_product(m.get(), w);
  std::vector<double> q(problem.q.data(), problem.q.data() + problem.size());
  std::vector<double> mu(problem.mu.data(), problem.mu.data() + problem.num_contacts());
  FrictionContactProblem fc{3, problem.num_contacts(), m.get(), q.data(), mu.data()};
  const OptionsPtr options = options_for(solver_id, tolerance, max_iterations);
  SiconosRun run;
  run.solution = Eigen::VectorXd::Zero(problem.size());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(problem.size());
  const std::clock_t start = std::clock();
  for (int call = 0; call < repeats; ++call) {
    run.solution.setZero();
    u.setZero();
    run.info = fc3d_driver(&fc, run.solution.data(), u.data(), options.get());
  }
  run.seconds = cpu_seconds_since(start) / repeats;
  run.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  run.own_error = options->dparam[SICONOS_DPARAM_RESIDU];
  return run;
}

}  // namespace impactbench::bench
