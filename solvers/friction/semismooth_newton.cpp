// nsn: semismooth Newton on the stacked Alart–Curnier function Φ(r) (alart_curnier.hpp),
//   J Δ = −Φ,  J = A + B W  (A, B block diagonal),
// with nonmonotone Armijo backtracking on ½‖Φ‖² (see kNonmonotoneMemory). W = Hᵀ M⁻¹ H of a
// real pile is rank-deficient (more contact rows than degrees of freedom), and then J is
// singular on the sticking and sliding contacts: the plain Newton step is dominated by a huge
// null-space component (on FCLIB's spheres-in-a-box it was 10³–10⁴ × ‖r‖, so no step was ever
// accepted). The direction is therefore taken from the Jacobian of the proximally regularised
// problem W + c_k D,
//   J_k = A + B (W + c_k D),  D = diag(W),  c_k = γ ‖Φ(r_k)‖ / ‖Φ(r_0)‖,
// which is nonsingular and tends to J as Φ → 0 (a regularised Newton method: the step is
// exact at the solution and the fast local rate is kept), while the line search still tests
// descent with the true J. When the factorisation fails or the step gives no sufficient
// decrease, a Levenberg–Marquardt direction (J_kᵀJ_k + λI)Δ = −J_kᵀΦ is tried, followed by one
// nonsmooth Gauss–Seidel sweep (the fallback). Dense W: LU with partial pivoting; sparse W:
// Eigen's SparseLU on the sparse J_k.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "solvers/friction/alart_curnier.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

/// γ of the regularisation c_k = γ ‖Φ_k‖ / ‖Φ_0‖. Measured on spheres-in-a-box: converged for
/// γ from 3e-3 to 3e-1 (170, 136, 163, 194 steps for 3e-3, 3e-2, 1e-1, 3e-1), stalled for
/// γ ≤ 1e-3 (the unregularised case); 3e-2 sits in the middle of that range.
constexpr double kRegularisation = 3e-2;

/// The line search is nonmonotone (Grippo–Lampariello–Lucidi): a step is accepted against the
/// largest merit of the last kNonmonotoneMemory iterations, not the current one. With the
/// monotone test, on spheres-in-a-box 137 of the 141 steps before convergence had their
/// Newton step cut (each then followed by an NSGS sweep: NSGS's slow rate, 4e-3 → 3e-6 in 130
/// steps); accepting a temporary increase lets full steps through. Iterations to 1e-10 on the
/// five FCLIB test files (Box_Stacks, Capsules, LMGC, Spheres, spheres-in-a-box), memory 1 /
/// 5 / 10 / 20: 6 13 14 6 142 / 6 11 92 6 95 / 6 11 34 6 32 / 6 11 200 6 26.
constexpr std::size_t kNonmonotoneMemory = 10;

struct NewtonSystem {
  Eigen::VectorXd phi;
  std::vector<LocalMatrix> a;  // per contact
  std::vector<LocalMatrix> b;
};

Eigen::VectorXd stacked_phi(const FrictionProblem& problem,
                            const std::vector<AlartCurnierParameters>& rho, VectorView r,
                            NewtonSystem* system) {
  const int d = problem.dimension;
  const CapacityVector u = contact_velocity(problem, r);
  Eigen::VectorXd phi(problem.size());
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    contact_part(phi, i, d) =
        system ? alart_curnier(problem.mu(i), rho[k], contact_part(r, i, d), contact_part(u, i, d),
                               &system->a[k], &system->b[k])
               : alart_curnier(problem.mu(i), rho[k], contact_part(r, i, d), contact_part(u, i, d));
  }
  return phi;
}

/// J = A + B (W + c D), D = diag(W) (c = 0: the true Jacobian), dense or sparse like W.
struct Jacobian {
  Eigen::MatrixXd dense;
  Eigen::SparseMatrix<double> sparse;
  bool is_sparse = false;
};

Jacobian assemble_jacobian(const FrictionProblem& problem, const NewtonSystem& system,
                           const std::vector<LocalMatrix>& blocks, double c) {
  const int d = problem.dimension;
  const int n = problem.size();
  Jacobian jacobian;
  jacobian.is_sparse = problem.is_sparse;
  if (!problem.is_sparse) {
    jacobian.dense.resize(n, n);
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      jacobian.dense.middleRows(i * d, d).noalias() =
          system.b[k] * problem.dense_W.middleRows(i * d, d);
      jacobian.dense.block(i * d, i * d, d, d) +=
          system.a[k] + c * system.b[k] * blocks[k].diagonal().asDiagonal();
    }
    return jacobian;
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(problem.sparse_W.nonZeros() * d + n * d));
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    for (int row = 0; row < d; ++row) {
      for (int col = 0; col < d; ++col) {
        const double local =
            system.a[k](row, col) + c * system.b[k](row, col) * blocks[k](col, col);
        if (local != 0.0) entries.emplace_back(i * d + row, i * d + col, local);
        const double factor = system.b[k](row, col);
        if (factor == 0.0) continue;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_W,
                                                                            i * d + col);
             it; ++it) {
          entries.emplace_back(i * d + row, static_cast<int>(it.col()), factor * it.value());
        }
      }
    }
  }
  jacobian.sparse.resize(n, n);
  jacobian.sparse.setFromTriplets(entries.begin(), entries.end());
  return jacobian;
}

/// J x = A x + B (W x) with the true J, contact by contact (for the line search's slope).
Eigen::VectorXd jacobian_times(const FrictionProblem& problem, const NewtonSystem& system,
                               const Eigen::VectorXd& x) {
  const int d = problem.dimension;
  const Eigen::VectorXd w_x = contact_velocity(problem, x) - problem.q;
  Eigen::VectorXd result(x.size());
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    contact_part(result, i, d).noalias() =
        system.a[k] * contact_part(x, i, d) + system.b[k] * contact_part(w_x, i, d);
  }
  return result;
}

/// Newton direction −J⁻¹Φ; empty if the factorisation fails or the result is not finite.
Eigen::VectorXd newton_direction(const Jacobian& jacobian, const Eigen::VectorXd& phi) {
  Eigen::VectorXd step;
  if (!jacobian.is_sparse) {
    step = -jacobian.dense.partialPivLu().solve(phi);
  } else {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(jacobian.sparse);
    if (lu.info() != Eigen::Success) return {};
    step = -lu.solve(phi);
  }
  if (!step.allFinite()) return {};
  return step;
}

/// Levenberg–Marquardt direction −(JᵀJ + λI)⁻¹ JᵀΦ, a descent direction for ½‖Φ‖² even when
/// J is singular (W rank-deficient: more contact rows than degrees of freedom).
Eigen::VectorXd levenberg_marquardt_direction(const Jacobian& jacobian,
                                              const Eigen::VectorXd& phi) {
  Eigen::VectorXd step;
  if (!jacobian.is_sparse) {
    Eigen::MatrixXd normal = jacobian.dense.transpose() * jacobian.dense;
    const double lambda = 1e-10 * normal.diagonal().maxCoeff() + 1e-300;
    normal.diagonal().array() += lambda;
    step = -normal.ldlt().solve(jacobian.dense.transpose() * phi);
  } else {
    const Eigen::SparseMatrix<double> transpose = jacobian.sparse.transpose();
    Eigen::SparseMatrix<double> normal = transpose * jacobian.sparse;
    const double lambda = 1e-10 * Eigen::VectorXd(normal.diagonal()).maxCoeff() + 1e-300;
    for (int k = 0; k < normal.rows(); ++k) normal.coeffRef(k, k) += lambda;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) return {};
    step = -ldlt.solve(transpose * phi);
  }
  if (!step.allFinite()) return {};
  return step;
}

}  // namespace

Outcome solve_semismooth_newton(const FrictionProblem& problem, const SolverOptions& options,
                                CapacityVector& r) {
  const std::vector<LocalMatrix> blocks = diagonal_blocks(problem);
  std::vector<AlartCurnierParameters> rho;
  rho.reserve(blocks.size());
  for (const LocalMatrix& block : blocks) {
    if (!(block(0, 0) > 0.0)) return nonpositive_normal_diagonal();
    AlartCurnierParameters parameters = alart_curnier_parameters(block);
    parameters.rho_n *= options.rho_scale;
    parameters.rho_t *= options.rho_scale;
    rho.push_back(parameters);
  }
  NewtonSystem system;
  system.a.resize(blocks.size());
  system.b.resize(blocks.size());
  Outcome outcome;
  int fallbacks = 0;
  double residual = friction_residual(problem, r);
  double initial_phi_norm = 0.0;
  std::vector<double> recent_merits;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    system.phi = stacked_phi(problem, rho, r, &system);
    const double merit = system.phi.squaredNorm();
    if (outcome.iterations == 1) initial_phi_norm = std::sqrt(merit);
    recent_merits.push_back(merit);
    if (recent_merits.size() > kNonmonotoneMemory) recent_merits.erase(recent_merits.begin());
    const double reference_merit = *std::max_element(recent_merits.begin(), recent_merits.end());
    const double c =
        initial_phi_norm > 0.0 ? kRegularisation * std::sqrt(merit) / initial_phi_norm : 0.0;
    const Jacobian jacobian = assemble_jacobian(problem, system, blocks, c);
    // Armijo on ½‖Φ‖² with the directional derivative ΦᵀJΔ of each candidate direction.
    // Returns the accepted step length (0 if none).
    const auto line_search = [&](const Eigen::VectorXd& step) {
      if (step.size() == 0) return 0.0;
      const double slope = system.phi.dot(jacobian_times(problem, system, step));
      if (!(slope < 0.0)) return 0.0;
      double alpha = 1.0;
      for (int halving = 0; halving < 20; ++halving, alpha *= 0.5) {
        const Eigen::VectorXd trial = r + alpha * step;
        if (stacked_phi(problem, rho, trial, nullptr).squaredNorm() <=
            reference_merit + 2e-4 * alpha * slope) {
          r = trial;
          return alpha;
        }
      }
      return 0.0;
    };
    // A full Newton step is kept as is; a damped or Levenberg–Marquardt step (slow, far from
    // the solution or on a singular J) is followed by one NSGS sweep, so an iteration never
    // does worse than NSGS.
    const double full_step = line_search(newton_direction(jacobian, system.phi));
    if (full_step < 1.0) {
      if (full_step == 0.0) line_search(levenberg_marquardt_direction(jacobian, system.phi));
      ++fallbacks;
      nonsmooth_gauss_seidel_sweep(problem, blocks, r);
    }
    residual = friction_residual(problem, r);
    if (const auto stop = options.stop_status(outcome.iterations, residual)) {
      outcome.status = *stop;
      if (*stop == SolverStatus::kStopped) outcome.message = "stopped by the caller";
      return outcome;
    }
  }
  outcome.iterations = options.max_iterations;
  outcome.message =
      "iteration limit reached (" + std::to_string(fallbacks) + " fallback iterations)";
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
