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
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "solvers/common/number_text.hpp"
#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_residual.hpp"

namespace impactbench::solvers::lcp {
namespace {

// Every test is relative, so that scaling the problem (M and q, or q alone, or one unknown)
// scales nothing but the answer: an absolute threshold called a solvable problem with
// ‖q‖ ~ 1e-12 unsolvable (every ratio "tied" at 0 and the lexicographic rule chose blindly).
//
// A column entry c_r is a pivot candidate when it exceeds kPivotTolerance times the size of
// what it is computed from, max_k |B⁻¹_rk| ‖a‖∞ (below that it is rounding, whatever the
// scale of row r's variable). Σ_k |B⁻¹_rk| |a_k| is not enough: for a w column it is |c_r|
// itself, and a rounding-size entry (1e-16 measured on degenerate_psd_problem(40, 0)) became a
// pivot that ended in a secondary ray.
constexpr double kPivotTolerance = 1e-11;
// Two ratios x_r / c_r tie (and go to the lexicographic rule) when they differ by less than
// their rounding: kTieTolerance times the ratio, or than the rounding of x_r, of the order of
// max_k |B⁻¹_rk| ‖q‖∞, divided by c_r. (Σ_k |B⁻¹_rk| |q_k| was too small where q has zeros:
// a disk-pile step of moreau with lemke then ended in a secondary ray.) A zero ratio and one of
// rounding size are then a tie whatever the scale of q; with a scale taken from the other ratios,
// one large ratio would have made every small one tie.
constexpr double kTieTolerance = 1e-11;

/// |a − b| within the relative tolerance, or within `rounding` (an absolute amount).
bool ties(double a, double b, double rounding) {
  return std::abs(a - b) <= std::max(rounding, kTieTolerance * std::max(std::abs(a), std::abs(b)));
}

// B⁻¹ −= o · p for the n × n column-major B⁻¹ and size_r = max_k |B⁻¹_rk| of the result, in
// one pass: two more passes over B⁻¹ per pivot for the sizes (as they were first computed)
// made Lemke 1.6-2.4 times slower per pivot. Four columns at a time, so each row's size is
// loaded and stored once per four entries. Each entry is b − o·p, the same operation as
// Eigen's outer-product update: the same bits. The buffers are the tableau's own and never
// overlap; saying so (__restrict) lets the compiler vectorise the loop, which it did by itself
// only while o was a fresh local allocation.
void update_inverse_and_row_sizes(double* __restrict binv, const double* __restrict o,
                                  const double* __restrict p, double* __restrict size, int n) {
  constexpr int kColumns = 4;
  std::fill(size, size + n, 0.0);
  int k = 0;
  for (; k + kColumns <= n; k += kColumns) {
    double* __restrict b0 = binv + static_cast<std::ptrdiff_t>(k) * n;
    double* __restrict b1 = b0 + n;
    double* __restrict b2 = b1 + n;
    double* __restrict b3 = b2 + n;
    const double p0 = p[k], p1 = p[k + 1], p2 = p[k + 2], p3 = p[k + 3];
    for (int i = 0; i < n; ++i) {
      b0[i] -= p0 * o[i];
      b1[i] -= p1 * o[i];
      b2[i] -= p2 * o[i];
      b3[i] -= p3 * o[i];
      size[i] = std::max(
          std::max(std::max(size[i], std::abs(b0[i])), std::max(std::abs(b1[i]), std::abs(b2[i]))),
          std::abs(b3[i]));
    }
  }
  for (; k < n; ++k) {
    double* __restrict b = binv + static_cast<std::ptrdiff_t>(k) * n;
    const double pk = p[k];
    for (int i = 0; i < n; ++i) {
      b[i] -= pk * o[i];
      size[i] = std::max(size[i], std::abs(b[i]));
    }
  }
}

// The tableau's vectors live in one buffer; its methods take columns by reference, either kind.
using Column = Eigen::Map<Eigen::VectorXd, Eigen::Aligned16>;
using ColumnRef = Eigen::Ref<const Eigen::VectorXd>;

/// k rounded up to even: offsets into the tableau's buffer stay 16-byte aligned.
constexpr int padded(int k) {
  return k + (k & 1);
}

/// The tableau's storage: B⁻¹, the row sizes, x and the work buffers in one block (each part
/// on an even index, so 16-byte aligned like an Eigen vector of its own and Eigen's kernels
/// take the same paths), the basis, and the tied rows of a ratio test with their rounding.
struct LemkeStorage {
  // Not zeroed (the tableau sets every entry it reads): a vector zero-filled a large problem's
  // whole B⁻¹ at every solve.
  std::unique_ptr<double[]> values;
  std::size_t capacity = 0;
  std::vector<int> basis;
  std::vector<int> rows;
  std::vector<double> rounding;

  /// Room for the tableau of n unknowns, kept when there is enough already.
  void reserve(int n) {
    const auto needed = static_cast<std::size_t>(padded(n * n) + 5 * padded(n));
    if (capacity < needed) {
      values = std::make_unique_for_overwrite<double[]>(needed);
      capacity = needed;
    }
    basis.resize(static_cast<std::size_t>(n));
  }
};

/// Storage for one solve. Problems up to kKeptSize unknowns reuse storage kept per thread: a
/// solve of Siconos' small test problems (n ≤ 9, a few pivots) was a third allocations, and the
/// event engine solves such a problem at every planar impact and constrained right-hand side.
/// Larger problems, where the pivots dominate, allocate their own and give it back, so a thread
/// keeps at most about kKeptSize² values. A solve started while another one holds the kept
/// storage on the same thread (from a caller's monitor) allocates its own too.
class StorageLease {
 public:
  explicit StorageLease(int n) {
    Kept& kept = this_thread();
    if (n <= kKeptSize && !kept.in_use) {
      kept.in_use = true;
      kept_ = &kept;
      storage_ = &kept.storage;
    } else {
      own_ = std::make_unique<LemkeStorage>();
      storage_ = own_.get();
    }
    storage_->reserve(n);
  }
  ~StorageLease() {
    if (kept_ != nullptr) kept_->in_use = false;
  }
  StorageLease(const StorageLease&) = delete;
  StorageLease& operator=(const StorageLease&) = delete;

  LemkeStorage& storage() const { return *storage_; }

 private:
  static constexpr int kKeptSize = 64;
  struct Kept {
    LemkeStorage storage;
    bool in_use = false;
  };
  static Kept& this_thread() {
    thread_local Kept kept;
    return kept;
  }

  Kept* kept_ = nullptr;  // not owned: the thread's kept storage, when this lease holds it
  std::unique_ptr<LemkeStorage> own_;
  LemkeStorage* storage_ = nullptr;  // kept_->storage or *own_
};

class LemkeTableau {
 public:
  // Variables: w_i ↦ i, z_j ↦ n + j, z0 ↦ 2n. The initial basis is w (B = I, x = q).
  LemkeTableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, LemkeStorage& storage)
      : M_(M),
        q_(q),
        n_(static_cast<int>(q.size())),
        basis_(storage.basis),
        binv_(storage.values.get(), n_, n_),
        row_size_(binv_.data() + padded(n_ * n_), n_),
        x_(row_size_.data() + padded(n_), n_),
        column_(x_.data() + padded(n_), n_),
        others_(column_.data() + padded(n_), n_),
        pivot_row_(others_.data() + padded(n_), n_),
        q_size_(q.size() > 0 ? q.cwiseAbs().maxCoeff() : 0.0),
        rows_(storage.rows),
        rounding_(storage.rounding) {
    static_assert(__STDCPP_DEFAULT_NEW_ALIGNMENT__ >= 16);
    binv_.setIdentity();
    row_size_.setOnes();
    x_ = q;
    for (int i = 0; i < n_; ++i) basis_[i] = i;
  }

  int z0() const { return 2 * n_; }
  int complement(int variable) const { return variable < n_ ? variable + n_ : variable - n_; }
  int basic_variable(int row) const { return basis_[row]; }

  // c = B⁻¹ a for the column a of `variable` in [I, −M, −d], in a buffer the tableau keeps
  // (valid until the next call; a solve of a small problem was mostly allocations).
  const Column& column(int variable) {
    if (variable < n_) {
      column_ = binv_.col(variable);
    } else if (variable < 2 * n_) {
      column_.noalias() = binv_ * M_.col(variable - n_);
      column_ = -column_;
    } else {
      column_ = -binv_.rowwise().sum();
    }
    return column_;
  }

  // ‖a‖∞ of the column of `variable` in [I, −M, −d].
  double column_size(int variable) const {
    return variable < n_ || variable == 2 * n_ ? 1.0 : M_.col(variable - n_).cwiseAbs().maxCoeff();
  }

  // Lexicographic minimum of (x_r, B⁻¹_r,:) / c_r over the rows with c_r > 0; −1 if there is
  // none (a ray). When the plain ratio ties with the row of z0, z0 leaves: that ends the method
  // with x ≥ 0, whichever tied row is chosen. `a_size`: ‖a‖∞ of the entering column.
  int ratio_test(ColumnRef c, double a_size) {
    std::vector<int>& rows = rows_;
    rows.clear();
    double best = 0.0;
    double best_noise = 0.0;
    for (int r = 0; r < n_; ++r) {
      // c_r is computed from B⁻¹'s row r and a: below max_k |B⁻¹_rk| ‖a‖∞ it is rounding (B⁻¹'s
      // row carries the rounding of all the pivots that made it, so an entry of a w column far
      // below its row is rounding too).
      if (!(c(r) > kPivotTolerance * (row_size_(r) * a_size))) continue;
      const double ratio = x_(r) / c(r);
      // The rounding of x_r: max_k |B⁻¹_rk| ‖q‖∞.
      const double noise = kTieTolerance * (row_size_(r) * q_size_) / c(r);
      const bool tie = ties(ratio, best, std::max(noise, best_noise));
      if (rows.empty() || (ratio < best && !tie)) {
        rows.assign(1, r);
        best = ratio;
        best_noise = noise;
      } else if (tie) {
        rows.push_back(r);
        if (ratio < best) best = ratio, best_noise = noise;
      }
    }
    if (rows.size() <= 1) return rows.empty() ? -1 : rows.front();
    for (int r : rows) {
      if (basis_[r] == z0()) return r;
    }
    return lexicographic_minimum(c);
  }

  // The first pivot: z0 enters with column −d, and the row with the lexicographically smallest
  // (x_r, B⁻¹_r,:) / d_r leaves; after it every row of the tableau is lexico-positive.
  int initial_row() {
    std::vector<int>& rows = rows_;
    rows.clear();
    double best = 0.0;
    const double scale = kTieTolerance * x_.cwiseAbs().maxCoeff();  // B = I: x = q
    for (int r = 0; r < n_; ++r) {
      if (rows.empty() || (x_(r) < best && !ties(x_(r), best, scale))) {
        rows.assign(1, r);
        best = x_(r);
      } else if (ties(x_(r), best, scale)) {
        rows.push_back(r);
        best = std::min(best, x_(r));
      }
    }
    if (rows.size() == 1) return rows.front();
    column_.setOnes();  // d, the entering column of z0 (B = I)
    return lexicographic_minimum(column_);
  }

  // Gauss–Jordan step: `entering` becomes basic in `row`.
  void pivot(int row, ColumnRef c, int entering) {
    const double p = c(row);
    binv_.row(row) /= p;
    x_(row) /= p;
    others_ = c;
    others_(row) = 0.0;
    pivot_row_ = binv_.row(row);
    update_inverse_and_row_sizes(binv_.data(), others_.data(), pivot_row_.data(), row_size_.data(),
                                 n_);
    x_ -= others_ * x_(row);
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
  // Lexicographic minimum among the tied rows in rows_ (narrowed in place).
  int lexicographic_minimum(ColumnRef c) {
    std::vector<int>& rows = rows_;
    // Rounding of B⁻¹_rk / c_r: relative to the size of row r of B⁻¹ (its entries are
    // computed together), divided by c_r.
    std::vector<double>& rounding = rounding_;
    rounding.clear();
    for (int r : rows) rounding.push_back(kTieTolerance * row_size_(r) / c(r));
    for (int k = 0; k < n_ && rows.size() > 1; ++k) {
      std::size_t best = 0;
      for (std::size_t j = 1; j < rows.size(); ++j)
        if (binv_(rows[j], k) / c(rows[j]) < binv_(rows[best], k) / c(rows[best])) best = j;
      const double best_ratio = binv_(rows[best], k) / c(rows[best]);
      const double best_rounding = rounding[best];
      // Keep the tied rows, in order (a stable in-place filter).
      std::size_t kept = 0;
      for (std::size_t j = 0; j < rows.size(); ++j) {
        if (ties(binv_(rows[j], k) / c(rows[j]), best_ratio,
                 std::max(rounding[j], best_rounding))) {
          rows[kept] = rows[j];
          rounding[kept] = rounding[j];
          ++kept;
        }
      }
      rows.resize(kept);
      rounding.resize(kept);
    }
    return rows.front();
  }

  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& q_;
  int n_;
  std::vector<int>& basis_;  // basis_[row] = variable basic in that row
  // Parts of LemkeStorage::values (operator new aligns it to 16 bytes,
  // __STDCPP_DEFAULT_NEW_ALIGNMENT__).
  Eigen::Map<Eigen::MatrixXd, Eigen::Aligned16> binv_;
  Column row_size_;  // max_k |B⁻¹_rk| per row, kept by update_inverse_and_row_sizes()
  Column x_;
  // Work buffers kept across pivots: the entering column, the pivot's update vectors, the
  // tied rows of a ratio test and their rounding.
  Column column_, others_;
  Eigen::Map<Eigen::RowVectorXd, Eigen::Aligned16> pivot_row_;
  double q_size_;  // ‖q‖∞
  std::vector<int>& rows_;
  std::vector<double>& rounding_;
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

  const StorageLease lease(n);
  LemkeTableau tableau(M, problem.q, lease.storage());
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
    const auto& c = tableau.column(entering);
    const int row = tableau.ratio_test(c, tableau.column_size(entering));
    if (row < 0) {
      result.z = tableau.z();
      // With the covering variable z0 down to rounding, the basis already holds a solution:
      // the ray is one of rounding-size entries, and the answer meets the tolerance as any
      // solver's answer does (moreau with lemke on disk_pile stopped at t = 0.273 on such a
      // ray with residual 5e-12).
      const double residual = natural_map_residual(result.z, lcp_velocity(problem, result.z));
      if (residual <= options.tolerance) {
        result.status = SolverStatus::kConverged;
        result.message = "secondary ray after " + std::to_string(result.iterations) +
                         " pivots with z already a solution (residual " +
                         output::number_text(residual) + ")";
        return result;
      }
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
    if (!options.keep_going(result.iterations, std::numeric_limits<double>::quiet_NaN())) {
      result.z = tableau.z();
      result.status = SolverStatus::kStopped;
      result.message = "stopped after " + std::to_string(result.iterations) + " pivots";
      return result;
    }
    entering = tableau.complement(leaving);
  }

  // Rounding accumulated over many pivots may leave the residual above tolerance: then try a
  // fresh factorisation of the final basis and keep whichever solution is better. The answer's
  // w and residual go back with it, so that the driver need not compute them again.
  result.z = tableau.z();
  result.w = lcp_velocity(problem, result.z);
  result.residual = natural_map_residual(result.z, result.w);
  if (!(result.residual <= options.tolerance)) {
    Eigen::VectorXd refined = tableau.z_refactored();
    if (refined.allFinite()) {
      Eigen::VectorXd refined_w = lcp_velocity(problem, refined);
      const double refined_residual = natural_map_residual(refined, refined_w);
      if (refined_residual < result.residual) {
        result.z = std::move(refined);
        result.w = std::move(refined_w);
        result.residual = refined_residual;
      }
    }
  }
  result.status = SolverStatus::kConverged;
  return result;
}

}  // namespace impactbench::solvers::lcp
