// Lemke's complementary pivoting method (Cottle–Pang–Stone, "The Linear Complementarity
// Problem", §4.4) on the augmented system
//
//     I w − M z − d z0 = q,     d = (1, …, 1) the covering vector.
//
// The tableau is kept as the explicit inverse B⁻¹ of the basis matrix and the basic values
// x = B⁻¹ q. z0 enters first, taking the row of the most negative q_i / d_i; afterwards the
// complement of the variable that just left enters, until z0 leaves (a solution) or the
// entering column has no positive entry (a secondary ray: no solution reachable by pivoting).
//
// Degeneracy: several rows may tie in the minimum-ratio test. Breaking the tie arbitrarily can
// make the method cycle; the lexicographic rule compares the rows (x_r, B⁻¹_r,:) / c_r
// lexicographically instead. Its rows are linearly independent, so the choice is unique, and
// the tableau stays lexico-positive, so no basis repeats and the method terminates.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers::lcp {
namespace {

// A column entry below this (relative to the column's largest entry) is not a pivot candidate.
constexpr double kPivotTolerance = 1e-11;
// Two ratios closer than this (relative) are treated as a tie and go to the lexicographic rule.
constexpr double kTieTolerance = 1e-11;

bool ties(double a, double b) {
  return std::abs(a - b) <= kTieTolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

class LemkeTableau {
 public:
  // Variables: w_i ↦ i, z_j ↦ n + j, z0 ↦ 2n. The initial basis is w (B = I, x = q).
  LemkeTableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q)
      : M_(M),
        q_(q),
        n_(static_cast<int>(q.size())),
        basis_(n_),
        binv_(Eigen::MatrixXd::Identity(n_, n_)),
        x_(q) {
    for (int i = 0; i < n_; ++i) basis_[i] = i;
  }

  int z0() const { return 2 * n_; }
  int complement(int variable) const { return variable < n_ ? variable + n_ : variable - n_; }
  int basic_variable(int row) const { return basis_[row]; }

  // c = B⁻¹ a for the column a of `variable` in [I, −M, −d].
  Eigen::VectorXd column(int variable) const {
    if (variable < n_) return binv_.col(variable);
    if (variable < 2 * n_) return -(binv_ * M_.col(variable - n_));
    return -binv_.rowwise().sum();
  }

  // Lexicographic minimum of (x_r, B⁻¹_r,:) / c_r over the rows with c_r > 0; −1 if there is
  // none (a ray). When the plain ratio ties with the row of z0, z0 leaves: that ends the method
  // with x ≥ 0, whichever tied row is chosen.
  int ratio_test(const Eigen::VectorXd& c) const {
    const double threshold = kPivotTolerance * std::max(1.0, c.cwiseAbs().maxCoeff());
    std::vector<int> rows;
    double best = 0.0;
    for (int r = 0; r < n_; ++r) {
      if (c(r) <= threshold) continue;
      const double ratio = x_(r) / c(r);
      if (rows.empty() || (ratio < best && !ties(ratio, best))) {
        rows.assign(1, r);
        best = ratio;
      } else if (ties(ratio, best)) {
        rows.push_back(r);
        best = std::min(best, ratio);
      }
    }
    if (rows.size() <= 1) return rows.empty() ? -1 : rows.front();
    for (int r : rows) {
      if (basis_[r] == z0()) return r;
    }
    return lexicographic_minimum(std::move(rows), c);
  }

  // The first pivot: z0 enters with column −d, and the row with the lexicographically smallest
  // (x_r, B⁻¹_r,:) / d_r leaves; after it every row of the tableau is lexico-positive.
  int initial_row() const {
    std::vector<int> rows;
    double best = 0.0;
    for (int r = 0; r < n_; ++r) {
      if (rows.empty() || (x_(r) < best && !ties(x_(r), best))) {
        rows.assign(1, r);
        best = x_(r);
      } else if (ties(x_(r), best)) {
        rows.push_back(r);
        best = std::min(best, x_(r));
      }
    }
    return rows.size() == 1 ? rows.front()
                            : lexicographic_minimum(std::move(rows), Eigen::VectorXd::Ones(n_));
  }

  // Gauss–Jordan step: `entering` becomes basic in `row`.
  void pivot(int row, const Eigen::VectorXd& c, int entering) {
    const double p = c(row);
    binv_.row(row) /= p;
    x_(row) /= p;
    Eigen::VectorXd others = c;
    others(row) = 0.0;
    const Eigen::RowVectorXd pivot_row = binv_.row(row);
    binv_.noalias() -= others * pivot_row;
    x_ -= others * x_(row);
    basis_[row] = entering;
  }

  // z read off the current basis (z_j = x_r where z_j is basic in row r).
  Eigen::VectorXd z() const {
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n_);
    for (int r = 0; r < n_; ++r) {
      if (basis_[r] >= n_ && basis_[r] < 2 * n_) z(basis_[r] - n_) = x_(r);
    }
    return z;
  }

  // z from a fresh LU solve of B x = q: removes the rounding accumulated by the rank-one
  // updates of B⁻¹ over many pivots. Only valid once z0 has left the basis.
  Eigen::VectorXd z_refactored() const {
    Eigen::MatrixXd B(n_, n_);
    for (int r = 0; r < n_; ++r) {
      const int v = basis_[r];
      B.col(r) =
          v < n_ ? Eigen::VectorXd(Eigen::VectorXd::Unit(n_, v)) : Eigen::VectorXd(-M_.col(v - n_));
    }
    const Eigen::VectorXd x = B.partialPivLu().solve(q_);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n_);
    for (int r = 0; r < n_; ++r) {
      if (basis_[r] >= n_) z(basis_[r] - n_) = x(r);
    }
    return z;
  }

 private:
  int lexicographic_minimum(std::vector<int> rows, const Eigen::VectorXd& c) const {
    for (int k = 0; k < n_ && rows.size() > 1; ++k) {
      double best = binv_(rows.front(), k) / c(rows.front());
      for (int r : rows) best = std::min(best, binv_(r, k) / c(r));
      std::erase_if(rows, [&](int r) { return !ties(binv_(r, k) / c(r), best); });
    }
    return rows.front();
  }

  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& q_;
  int n_;
  std::vector<int> basis_;  // basis_[row] = variable basic in that row
  Eigen::MatrixXd binv_;
  Eigen::VectorXd x_;
};

std::string variable_name(int variable, int n) {
  if (variable == 2 * n) return "z0";
  return (variable < n ? "w" : "z") + std::to_string(variable % n);
}

}  // namespace

LcpMethodResult solve_lemke(const LcpProblem& problem, const SolverOptions& options,
                            const Eigen::VectorXd& /*z_start: pivoting starts from w = q*/) {
  const int n = problem.size();
  Eigen::MatrixXd densified;
  if (problem.is_sparse) densified = Eigen::MatrixXd(problem.sparse_M);
  const Eigen::MatrixXd& M = problem.is_sparse ? densified : problem.dense_M;

  LemkeTableau tableau(M, problem.q);
  LcpMethodResult result;
  if (options.max_iterations < 1) {
    result.z = Eigen::VectorXd::Zero(n);
    result.status = SolverStatus::kMaxIterations;
    result.message = "no pivot allowed (max_iterations < 1)";
    return result;
  }
  // First pivot: z0 enters.
  const int first = tableau.initial_row();
  int entering = tableau.complement(tableau.basic_variable(first));
  tableau.pivot(first, tableau.column(tableau.z0()), tableau.z0());
  result.iterations = 1;

  while (true) {
    if (result.iterations >= options.max_iterations) {
      result.z = tableau.z();
      result.status = SolverStatus::kMaxIterations;
      result.message = "pivot limit " + std::to_string(options.max_iterations) + " reached";
      return result;
    }
    const Eigen::VectorXd c = tableau.column(entering);
    const int row = tableau.ratio_test(c);
    if (row < 0) {
      result.z = tableau.z();
      result.status = SolverStatus::kRayTermination;
      result.message = "secondary ray after " + std::to_string(result.iterations) +
                       " pivots: entering " + variable_name(entering, n) +
                       " is unbounded (no solution reachable by Lemke's method)";
      return result;
    }
    const int leaving = tableau.basic_variable(row);
    tableau.pivot(row, c, entering);
    ++result.iterations;
    if (leaving == tableau.z0()) break;
    entering = tableau.complement(leaving);
  }

  // Rounding accumulated over many pivots may leave the residual above tolerance: then try a
  // fresh factorisation of the final basis and keep whichever solution is better.
  result.z = tableau.z();
  const double residual = natural_map_residual(result.z, lcp_velocity(problem, result.z));
  if (!(residual <= options.tolerance)) {
    const Eigen::VectorXd refined = tableau.z_refactored();
    if (refined.allFinite() &&
        natural_map_residual(refined, lcp_velocity(problem, refined)) < residual) {
      result.z = refined;
    }
  }
  result.status = SolverStatus::kConverged;
  return result;
}

}  // namespace impactbench::solvers::lcp
