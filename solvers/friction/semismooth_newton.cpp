// nsn: semismooth Newton on the stacked Alart–Curnier function Φ(r) (alart_curnier.hpp),
//   J Δ = −Φ,  J = A + B W  (A, B block diagonal),
// with Armijo backtracking on ½‖Φ‖² (along a Newton direction ∇(½‖Φ‖²)ᵀΔ = −‖Φ‖²). When the
// linear solve fails or the line search finds no decrease, one nonsmooth Gauss–Seidel sweep is
// taken instead, which always makes progress on these problems. Dense W: LU with partial
// pivoting; sparse W: Eigen's SparseLU on the sparse J.
#include <cmath>

#include <Eigen/LU>
#include <Eigen/SparseLU>

#include "solvers/friction/alart_curnier.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"

namespace impactbench::solvers::friction_detail {
namespace {

struct NewtonSystem {
  Eigen::VectorXd phi;
  std::vector<LocalMatrix> a;  // per contact
  std::vector<LocalMatrix> b;
};

Eigen::VectorXd stacked_phi(const FrictionProblem& problem,
                            const std::vector<AlartCurnierParameters>& rho,
                            const Eigen::VectorXd& r, NewtonSystem* system) {
  const int d = problem.dimension;
  const Eigen::VectorXd u = contact_velocity(problem, r);
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

/// Newton direction −J⁻¹Φ; empty if the factorisation fails or the result is not finite.
Eigen::VectorXd newton_direction(const FrictionProblem& problem, const NewtonSystem& system) {
  const int d = problem.dimension;
  const int n = problem.size();
  Eigen::VectorXd step;
  if (!problem.is_sparse) {
    Eigen::MatrixXd jacobian(n, n);
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      jacobian.middleRows(i * d, d).noalias() = system.b[k] * problem.dense_W.middleRows(i * d, d);
      jacobian.block(i * d, i * d, d, d) += system.a[k];
    }
    step = -jacobian.partialPivLu().solve(system.phi);
  } else {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(problem.sparse_W.nonZeros() * d + n * d));
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      for (int row = 0; row < d; ++row) {
        for (int col = 0; col < d; ++col) {
          if (system.a[k](row, col) != 0.0)
            entries.emplace_back(i * d + row, i * d + col, system.a[k](row, col));
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
    Eigen::SparseMatrix<double> jacobian(n, n);
    jacobian.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(jacobian);
    if (lu.info() != Eigen::Success) return {};
    step = -lu.solve(system.phi);
  }
  if (!step.allFinite()) return {};
  const double check = step.norm();
  if (!std::isfinite(check)) return {};
  return step;
}

}  // namespace

Outcome solve_semismooth_newton(const FrictionProblem& problem, const SolverOptions& options,
                                Eigen::VectorXd& r) {
  const std::vector<LocalMatrix> blocks = diagonal_blocks(problem);
  std::vector<AlartCurnierParameters> rho;
  rho.reserve(blocks.size());
  for (const LocalMatrix& block : blocks) {
    if (!(block(0, 0) > 0.0))
      return {0, SolverStatus::kSingular, "a diagonal entry W_nn is not positive"};
    rho.push_back(alart_curnier_parameters(block));
  }
  NewtonSystem system;
  system.a.resize(blocks.size());
  system.b.resize(blocks.size());
  Outcome outcome;
  int fallbacks = 0;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    system.phi = stacked_phi(problem, rho, r, &system);
    const double merit = system.phi.squaredNorm();
    bool stepped = false;
    if (const Eigen::VectorXd step = newton_direction(problem, system); step.size() > 0) {
      double alpha = 1.0;
      for (int halving = 0; halving < 20 && !stepped; ++halving, alpha *= 0.5) {
        const Eigen::VectorXd trial = r + alpha * step;
        if (stacked_phi(problem, rho, trial, nullptr).squaredNorm() <=
            (1.0 - 1e-4 * alpha) * merit) {
          r = trial;
          stepped = true;
        }
      }
    }
    if (!stepped) {  // fallback: one exact-local-solve Gauss–Seidel sweep
      ++fallbacks;
      nonsmooth_gauss_seidel_sweep(problem, blocks, r);
    }
    if (friction_residual(problem, r) <= options.tolerance) {
      outcome.status = SolverStatus::kConverged;
      return outcome;
    }
  }
  outcome.iterations = options.max_iterations;
  outcome.message = "iteration limit reached (" + std::to_string(fallbacks) + " fallback sweeps)";
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
