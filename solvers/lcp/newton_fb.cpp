// Semismooth Newton method on the Fischer–Burmeister reformulation (De Luca, Facchinei, Kanzow,
// Math. Programming 75, 1996):
//
//     Φ_i(z) = √(z_i² + w_i²) − z_i − w_i,   w = M z + q,
//
// Φ(z) = 0 exactly when 0 ≤ z ⊥ w ≥ 0. An element of the generalized Jacobian is
// H = diag(a) + diag(b) M with a_i = z_i/ρ_i − 1, b_i = w_i/ρ_i − 1, ρ_i = ‖(z_i, w_i)‖; at the
// kink (z_i, w_i) = (0, 0) we take a_i = b_i = 1/√2 − 1, a limit along z_i = w_i. The step
// H d = −Φ is globalised by an Armijo search on Ψ = ½‖Φ‖², whose gradient is Hᵀ Φ; when H is
// singular, d is not a sufficient descent direction or the search fails, a Levenberg–Marquardt
// step and, last, the gradient step −Hᵀ Φ are tried. For a P0-matrix every stationary point of
// Ψ solves the LCP. Dense M uses a partial-pivoting LU, sparse M Eigen's SparseLU.
#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "solvers/common/number_text.hpp"
#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers::lcp {
namespace {

constexpr double kArmijoSlope = 1e-4;     // σ in Ψ(z + t d) ≤ Ψ(z) + σ t ∇Ψᵀ d
constexpr int kMaxBacktracks = 60;        // t down to 2⁻⁶⁰
constexpr double kDescentFactor = 1e-10;  // d accepted if ∇Ψᵀ d ≤ −kDescentFactor ‖d‖^2.1
constexpr double kDescentPower = 2.1;

struct FbState {
  Eigen::VectorXd w, phi, a, b;
  double merit = 0.0;  // Ψ = ½‖Φ‖²
};

FbState evaluate(const LcpProblem& problem, const Eigen::VectorXd& z) {
  FbState s;
  s.w = lcp_velocity(problem, z);
  const Eigen::Index n = z.size();
  s.phi.resize(n);
  s.a.resize(n);
  s.b.resize(n);
  const double kink = 1.0 / std::sqrt(2.0) - 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double rho = std::hypot(z(i), s.w(i));
    s.phi(i) = rho - z(i) - s.w(i);
    s.a(i) = rho > 0.0 ? z(i) / rho - 1.0 : kink;
    s.b(i) = rho > 0.0 ? s.w(i) / rho - 1.0 : kink;
  }
  s.merit = 0.5 * s.phi.squaredNorm();
  return s;
}

// ∇Ψ = Hᵀ Φ = a∘Φ + Mᵀ (b∘Φ).
Eigen::VectorXd merit_gradient(const LcpProblem& problem, const FbState& s) {
  const Eigen::VectorXd bphi = s.b.cwiseProduct(s.phi);
  Eigen::VectorXd g = s.a.cwiseProduct(s.phi);
  if (problem.is_sparse) {
    g.noalias() += problem.sparse_M.transpose() * bphi;
  } else {
    g.noalias() += problem.dense_M.transpose() * bphi;
  }
  return g;
}

// H = diag(a) + diag(b) M, stored like M.
struct Jacobian {
  Eigen::MatrixXd dense;
  Eigen::SparseMatrix<double> sparse;
  bool is_sparse = false;
};

Jacobian jacobian(const LcpProblem& problem, const FbState& s) {
  Jacobian H;
  H.is_sparse = problem.is_sparse;
  if (problem.is_sparse) {
    H.sparse = s.b.asDiagonal() * problem.sparse_M;
    for (Eigen::Index i = 0; i < H.sparse.rows(); ++i) H.sparse.coeffRef(i, i) += s.a(i);
    H.sparse.makeCompressed();
  } else {
    H.dense = s.b.asDiagonal() * problem.dense_M;
    H.dense.diagonal() += s.a;
  }
  return H;
}

// Solves H d = −Φ; nullopt when H is (numerically) singular.
std::optional<Eigen::VectorXd> newton_direction(const Jacobian& H, const FbState& s) {
  Eigen::VectorXd d;
  if (H.is_sparse) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(H.sparse);
    if (lu.info() != Eigen::Success) return std::nullopt;
    d = lu.solve(-s.phi);
    if (lu.info() != Eigen::Success) return std::nullopt;
  } else {
    d = H.dense.partialPivLu().solve(-s.phi);
  }
  // Partial pivoting does not report singularity: check that d actually solves the system.
  const Eigen::VectorXd defect =
      H.is_sparse ? Eigen::VectorXd(H.sparse * d + s.phi) : Eigen::VectorXd(H.dense * d + s.phi);
  if (!d.allFinite() || defect.norm() > 1e-8 * (1.0 + s.phi.norm())) return std::nullopt;
  return d;
}

// Levenberg–Marquardt step (HᵀH + λI) d = −∇Ψ with λ = ‖Φ‖ (Fan–Yuan): always a descent
// direction, and still fast near degenerate solutions where H is (nearly) singular.
std::optional<Eigen::VectorXd> levenberg_marquardt_direction(const Jacobian& H, const FbState& s,
                                                             const Eigen::VectorXd& gradient) {
  const double lambda = s.phi.norm();
  Eigen::VectorXd d;
  if (H.is_sparse) {
    Eigen::SparseMatrix<double> normal = H.sparse.transpose() * H.sparse;
    for (Eigen::Index i = 0; i < normal.rows(); ++i) normal.coeffRef(i, i) += lambda;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) return std::nullopt;
    d = ldlt.solve(-gradient);
  } else {
    Eigen::MatrixXd normal = H.dense.transpose() * H.dense;
    normal.diagonal().array() += lambda;
    Eigen::LLT<Eigen::MatrixXd> llt(normal);
    if (llt.info() != Eigen::Success) return std::nullopt;
    d = llt.solve(-gradient);
  }
  if (!d.allFinite()) return std::nullopt;
  return d;
}

// Armijo backtracking along d; nullopt if no step length gives sufficient decrease.
std::optional<std::pair<Eigen::VectorXd, FbState>> armijo(const LcpProblem& problem,
                                                          const Eigen::VectorXd& z,
                                                          const FbState& s,
                                                          const Eigen::VectorXd& d, double slope) {
  double t = 1.0;
  for (int k = 0; k < kMaxBacktracks; ++k, t *= 0.5) {
    Eigen::VectorXd trial = z + t * d;
    FbState next = evaluate(problem, trial);
    // Strict decrease as well: near rounding level the Armijo bound alone accepts a standstill.
    if (next.merit <= s.merit + kArmijoSlope * t * slope && next.merit < s.merit) {
      return std::make_pair(std::move(trial), std::move(next));
    }
  }
  return std::nullopt;
}

}  // namespace

LcpMethodResult solve_newton_fb(const LcpProblem& problem, const SolverOptions& options,
                                VectorView z_start) {
  LcpMethodResult result;
  Eigen::VectorXd z = z_start;
  FbState s = evaluate(problem, z);
  for (int k = 0;; ++k) {
    result.iterations = k;
    const double residual = natural_map_residual(z, s.w);
    if (residual <= options.tolerance) {
      result.status = SolverStatus::kConverged;
      break;
    }
    if (k > 0 && !options.keep_going(k, residual)) {
      result.status = SolverStatus::kStopped;
      result.message = "stopped after Newton step " + std::to_string(k);
      break;
    }
    if (k >= options.max_iterations) {
      result.status = SolverStatus::kMaxIterations;
      result.message = "Newton step limit " + std::to_string(options.max_iterations) + " reached";
      break;
    }
    const Eigen::VectorXd gradient = merit_gradient(problem, s);
    const Jacobian H = jacobian(problem, s);
    std::optional<std::pair<Eigen::VectorXd, FbState>> accepted;
    if (const auto d = newton_direction(H, s)) {
      const double slope = gradient.dot(*d);
      if (slope <= -kDescentFactor * std::pow(d->norm(), kDescentPower)) {
        accepted = armijo(problem, z, s, *d, slope);
      }
    }
    if (!accepted) {
      if (const auto d = levenberg_marquardt_direction(H, s, gradient)) {
        accepted = armijo(problem, z, s, *d, gradient.dot(*d));
      }
    }
    if (!accepted) {
      accepted = armijo(problem, z, s, -gradient, -gradient.squaredNorm());
    }
    if (!accepted) {
      result.status = SolverStatus::kStalled;
      result.message = "line search failed at Newton step " + std::to_string(k) + " (merit " +
                       output::number_text(s.merit) +
                       ", a stationary point of the "
                       "Fischer-Burmeister merit that does not solve the LCP)";
      break;
    }
    z = std::move(accepted->first);
    s = std::move(accepted->second);
  }
  result.z = z;
  return result;
}

}  // namespace impactbench::solvers::lcp
