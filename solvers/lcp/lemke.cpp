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
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "solvers/common/double_pair.hpp"
#include "solvers/common/number_text.hpp"
#include "solvers/common/thread_kept.hpp"
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

/// Fixed-size tableaux from this many unknowns take their rows in pairs (DoublePair), which the
/// compiler did not do by itself: 5-18 % less time per solve at 6 and 9 unknowns on Siconos'
/// test problems. At 2 to 4 the pairs did not pay (docs/performance.md).
constexpr int kPairsFromSize = 5;

/// The rows a tableau of N unknowns takes in pairs: all but an odd last one from kPairsFromSize
/// on, none below or at a size known only at run time (N = 0).
template <int N>
constexpr int kRowsInPairs = N >= kPairsFromSize ? N - N % 2 : 0;

// Rows (Rows = DoublePair: a pair of them; double: one) of four columns of an N × N column-major
// B⁻¹ from `b` on, minus o · p_k, written back, and the larger of `size` and their magnitudes, in
// the order of update_inverse_and_row_sizes() below (std::max keeps its first argument on a NaN,
// so the order is part of the result).
template <int N, typename Rows>
Rows update_four_columns(double* b, const double* p, Rows o, Rows size) {
  const Rows v0 = load_rows<Rows>(b) - p[0] * o;
  const Rows v1 = load_rows<Rows>(b + N) - p[1] * o;
  const Rows v2 = load_rows<Rows>(b + 2 * N) - p[2] * o;
  const Rows v3 = load_rows<Rows>(b + 3 * N) - p[3] * o;
  store_rows(b, v0);
  store_rows(b + N, v1);
  store_rows(b + 2 * N, v2);
  store_rows(b + 3 * N, v3);
  return larger(larger(larger(size, magnitude(v0)), larger(magnitude(v1), magnitude(v2))),
                magnitude(v3));
}

// The same for one column.
template <typename Rows>
Rows update_column(double* b, double p, Rows o, Rows size) {
  const Rows v = load_rows<Rows>(b) - p * o;
  store_rows(b, v);
  return larger(size, magnitude(v));
}

// update_inverse_and_row_sizes() below for a size N fixed at compile time from kPairsFromSize on:
// the same operations on each entry in the same order, on pairs of rows (the compiler did not
// vectorise these short loops) with o and the sizes held in registers, and an odd last row on
// its own.
template <int N>
void update_inverse_and_row_sizes_in_pairs(double* __restrict binv, const double* __restrict o,
                                           const double* __restrict p, double* __restrict size) {
  constexpr int kPairs = kRowsInPairs<N> / 2;
  constexpr int kLast = N - 1;  // the row without a pair when N is odd
  std::array<DoublePair, kPairs> o_pairs;
  std::array<DoublePair, kPairs> size_pairs;
  for (int j = 0; j < kPairs; ++j) {
    o_pairs[j] = load_pair(o + 2 * j);
    size_pairs[j] = DoublePair{0.0, 0.0};
  }
  double size_last = 0.0;
  int k = 0;
  for (; k + 4 <= N; k += 4) {
    double* columns = binv + static_cast<std::ptrdiff_t>(k) * N;
    for (int j = 0; j < kPairs; ++j) {
      size_pairs[j] = update_four_columns<N>(columns + 2 * j, p + k, o_pairs[j], size_pairs[j]);
    }
    if constexpr (N % 2 == 1) {
      size_last = update_four_columns<N>(columns + kLast, p + k, o[kLast], size_last);
    }
  }
  for (; k < N; ++k) {
    double* column = binv + static_cast<std::ptrdiff_t>(k) * N;
    for (int j = 0; j < kPairs; ++j) {
      size_pairs[j] = update_column(column + 2 * j, p[k], o_pairs[j], size_pairs[j]);
    }
    if constexpr (N % 2 == 1) size_last = update_column(column + kLast, p[k], o[kLast], size_last);
  }
  for (int j = 0; j < kPairs; ++j) store_pair(size + 2 * j, size_pairs[j]);
  if constexpr (N % 2 == 1) size[kLast] = size_last;
}

// B⁻¹ −= o · p for the n × n column-major B⁻¹ and size_r = max_k |B⁻¹_rk| of the result, in
// one pass: two more passes over B⁻¹ per pivot for the sizes (as they were first computed)
// made Lemke 1.6-2.4 times slower per pivot. Four columns at a time, so each row's size is
// loaded and stored once per four entries. Each entry is b − o·p, the same operation as
// Eigen's outer-product update: the same bits. The buffers are the tableau's own and never
// overlap; saying so (__restrict) lets the compiler vectorise the loop, which it did by itself
// only while o was a fresh local allocation (and does not at the small sizes fixed at compile
// time, which go to update_inverse_and_row_sizes_in_pairs() from kPairsFromSize on).
template <int N>
void update_inverse_and_row_sizes(double* __restrict binv, const double* __restrict o,
                                  const double* __restrict p, double* __restrict size,
                                  int dynamic_n) {
  if constexpr (kRowsInPairs<N> != 0) {
    update_inverse_and_row_sizes_in_pairs<N>(binv, o, p, size);
  } else {
    const int n = N > 0 ? N : dynamic_n;
    std::fill(size, size + n, 0.0);
    int k = 0;
    for (; k + 4 <= n; k += 4) {
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
        size[i] = std::max(std::max(std::max(size[i], std::abs(b0[i])),
                                    std::max(std::abs(b1[i]), std::abs(b2[i]))),
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
}
// c = −B a for the N × N column-major B: each c_i = −(the sum from 0 of B_ik a_k over k
// ascending), the order of Eigen's matrix–vector kernel, the first kRowsInPairs<N> rows in pairs.
template <int N>
void negated_product(const double* __restrict b, const double* __restrict a, double* __restrict c) {
  const auto negated_sum = [&]<typename Rows>(int i) {
    Rows sum{};
    for (int k = 0; k < N; ++k)
      sum += load_rows<Rows>(b + static_cast<std::ptrdiff_t>(k) * N + i) * a[k];
    store_rows(c + i, -sum);
  };
  int i = 0;
  for (; i < kRowsInPairs<N>; i += 2) negated_sum.template operator()<DoublePair>(i);
  for (; i < N; ++i) negated_sum.template operator()<double>(i);
}

/// k rounded up to even: parts of the tableau's buffer start 16-byte aligned.
constexpr int padded(int k) {
  return k + (k & 1);
}

/// The tableau's storage: B⁻¹, the row sizes, x and the work buffers in one block, the basis,
/// and the tied rows of a ratio test with their rounding.
struct LemkeStorage {
  // Not zeroed (the tableau sets every entry it reads): a vector zero-filled a large problem's
  // whole B⁻¹ at every solve.
  std::unique_ptr<double[]> values;
  std::size_t capacity = 0;
  std::vector<int> basis;
  std::vector<int> rows;
  std::vector<double> rounding;
  std::vector<double> ratios;

  /// Room for the tableau of n unknowns, kept when there is enough already.
  void reserve(int n) {
    const auto needed = static_cast<std::size_t>(padded(n * n) + 4 * padded(n));
    if (capacity < needed) {
      values = std::make_unique_for_overwrite<double[]>(needed);
      capacity = needed;
    }
    const auto size = static_cast<std::size_t>(n);
    if (basis.size() < size) {
      basis.resize(size);
      rows.resize(size);
      rounding.resize(size);
      ratios.resize(size);
    }
  }
};

/// Problems up to this many unknowns reuse storage kept per thread (ThreadKeptLease): a solve of
/// Siconos' small test problems (n ≤ 9, a few pivots) was a third allocations, and the event
/// engine solves such a problem at every planar impact and constrained right-hand side. Larger
/// problems, where the pivots dominate, allocate their own and give it back, so a thread keeps
/// at most about kKeptSize² values.
constexpr int kKeptSize = 64;

/// Problems of 2 to this many unknowns are solved by a tableau of that size fixed at compile
/// time, whose loops the compiler unrolls or vectorises without run-time set-up. At these sizes
/// loops of a run-time length spent more on their set-up than on their work. They cover Siconos'
/// small test problems, the event engine's planar contact problems up to four contacts (three
/// unknowns per contact with friction), and block Gauss–Seidel's spatial local problems (ten with
/// the default eight facets). The entering column is then summed by a plain loop in the order of
/// Eigen's matrix–vector kernel (each sum from 0, over k ascending): the same bits.
constexpr int kFixedSizeLimit = 12;

// The tableau works on plain arrays with loops written out: Siconos' test problems have 2 to 40
// unknowns and a few pivots, where each Eigen expression's set-up cost more than its arithmetic
// (a solve of n = 2 took 2,600 instructions). Every operation is the one Eigen did, in the same
// order (sums over k ascending, as Eigen's matrix–vector product forms them below 128 columns),
// so the pivots and answers are the same to the bit.
/// The tableau of N unknowns (N = 0: of the problem's size, known at run time).
template <int N>
class LemkeTableau {
 public:
  /// Whether the loops over rows take them in pairs (DoublePair; see kPairsFromSize).
  static constexpr bool kInPairs = kRowsInPairs<N> > 0;

  int n() const { return N > 0 ? N : n_; }

  // Variables: w_i ↦ i, z_j ↦ n + j, z0 ↦ 2n. The initial basis is w (B = I, x = q).
  LemkeTableau(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, LemkeStorage& storage)
      : M_(M),
        q_(q),
        n_(static_cast<int>(q.size())),
        binv_(storage.values.get()),
        row_size_(binv_ + padded(n() * n())),
        x_(row_size_ + padded(n())),
        column_(x_ + padded(n())),
        pivot_row_(column_ + padded(n())),
        basis_(storage.basis.data()),
        rows_(storage.rows.data()),
        rounding_(storage.rounding.data()),
        ratios_(storage.ratios.data()) {
    if constexpr (kInPairs) {
      start_in_pairs();
    } else {
      std::fill(binv_, binv_ + static_cast<std::ptrdiff_t>(n()) * n(), 0.0);
      for (int i = 0; i < n(); ++i) {
        binv_[static_cast<std::ptrdiff_t>(i) * n() + i] = 1.0;
        row_size_[i] = 1.0;
        x_[i] = q(i);
      }
    }
    for (int i = 0; i < n(); ++i) {
      q_size_ = std::max(q_size_, std::abs(q(i)));
      basis_[i] = i;
    }
  }

  int z0() const { return 2 * n(); }
  int complement(int variable) const { return variable < n() ? variable + n() : variable - n(); }
  int basic_variable(int row) const { return basis_[row]; }

  // c = B⁻¹ a for the column a of `variable` in [I, −M, −d], into the tableau's own buffer
  // (read by ratio_test and pivot).
  void enter(int variable) {
    double* __restrict c = column_;
    if (variable < n()) {
      copy_rows<kRowsInPairs<N>>(inverse_column(variable), n(), c);
    } else if (variable < 2 * n()) {
      const double* m = M_.col(variable - n()).data();
      if (N == 0) {
        // Eigen's kernel: vectorised, from 128 columns on summing in blocks of columns, and for
        // n = 1 a plain product.
        Eigen::Map<Eigen::VectorXd> entering(c, n());
        entering.noalias() = Eigen::Map<const Eigen::MatrixXd>(binv_, n(), n()) *
                             Eigen::Map<const Eigen::VectorXd>(m, n());
        entering = -entering;
        return;
      }
      negated_product<N>(binv_, m, c);
    } else {
      // z0 enters only at the first pivot, where B⁻¹ = I: −d.
      fill_rows<kRowsInPairs<N>>(c, n(), -1.0);
    }
  }

  // ‖a‖∞ of the column of `variable` in [I, −M, −d].
  double column_size(int variable) const {
    return variable < n() || variable == 2 * n() ? 1.0
                                                 : M_.col(variable - n()).cwiseAbs().maxCoeff();
  }

  // Lexicographic minimum of (x_r, B⁻¹_r,:) / c_r over the rows with c_r > 0; −1 if there is
  // none (a ray). When the plain ratio ties with the row of z0, z0 leaves: that ends the method
  // with x ≥ 0, whichever tied row is chosen. `a_size`: ‖a‖∞ of the entering column.
  int ratio_test(double a_size) {
    const double* c = column_;
    tied_ = 0;
    double best = 0.0;
    double best_noise = 0.0;
    for (int r = 0; r < n(); ++r) {
      // c_r is computed from B⁻¹'s row r and a: below max_k |B⁻¹_rk| ‖a‖∞ it is rounding (B⁻¹'s
      // row carries the rounding of all the pivots that made it, so an entry of a w column far
      // below its row is rounding too).
      if (!(c[r] > kPivotTolerance * (row_size_[r] * a_size))) continue;
      const double ratio = x_[r] / c[r];
      // The rounding of x_r: max_k |B⁻¹_rk| ‖q‖∞.
      const double noise = kTieTolerance * (row_size_[r] * q_size_) / c[r];
      const bool tie = ties(ratio, best, std::max(noise, best_noise));
      if (tied_ == 0 || (ratio < best && !tie)) {
        rows_[0] = r;
        tied_ = 1;
        best = ratio;
        best_noise = noise;
      } else if (tie) {
        rows_[tied_++] = r;
        if (ratio < best) best = ratio, best_noise = noise;
      }
    }
    if (tied_ <= 1) return tied_ == 0 ? -1 : rows_[0];
    for (int j = 0; j < tied_; ++j) {
      if (basis_[rows_[j]] == z0()) return rows_[j];
    }
    return lexicographic_minimum();
  }

  // The first pivot: z0 enters with column −d, and the row with the lexicographically smallest
  // (x_r, B⁻¹_r,:) / d_r leaves; after it every row of the tableau is lexico-positive.
  int initial_row() {
    tied_ = 0;
    double best = 0.0;
    const double scale = kTieTolerance * q_size_;  // B = I: x = q
    for (int r = 0; r < n(); ++r) {
      if (tied_ == 0 || (x_[r] < best && !ties(x_[r], best, scale))) {
        rows_[0] = r;
        tied_ = 1;
        best = x_[r];
      } else if (ties(x_[r], best, scale)) {
        rows_[tied_++] = r;
        best = std::min(best, x_[r]);
      }
    }
    if (tied_ == 1) return rows_[0];
    fill_rows<kRowsInPairs<N>>(column_, n(), 1.0);  // d, the entering column of z0 (B = I)
    return lexicographic_minimum();
  }

  // Gauss–Jordan step: `entering`, whose column enter() formed, becomes basic in `row`.
  void pivot(int row, int entering) {
    const double p = column_[row];
    if (row < kRowsInPairs<N>) {
      divide_pivot_row_in_pairs(row, p);
    } else {
      for (int k = 0; k < n(); ++k) {
        double& b = inverse_column(k)[row];
        b /= p;
        pivot_row_[k] = b;
      }
      x_[row] /= p;
      column_[row] = 0.0;  // the column is now the update's other factor
    }
    update_inverse_and_row_sizes<N>(binv_, column_, pivot_row_, row_size_, n());
    const double x_row = x_[row];
    double* __restrict x = x_;
    const double* __restrict other = column_;
    int i = 0;
    for (; i < kRowsInPairs<N>; i += 2) {
      store_pair(x + i, load_pair(x + i) - load_pair(other + i) * x_row);
    }
    for (; i < n(); ++i) x[i] -= other[i] * x_row;
    basis_[row] = entering;
  }

  // z read off the current basis (z_j = x_r where z_j is basic in row r), into z's storage.
  void write_z(CapacityVector& z) const {
    z.resize(n());
    std::fill_n(z.data(), n(), 0.0);
    for (int r = 0; r < n(); ++r) {
      if (basis_[r] >= n() && basis_[r] < 2 * n()) z(basis_[r] - n()) = x_[r];
    }
  }

  // w = M z + q for the answer z, into w's storage. A fixed size sums each row by a plain loop
  // in the order of Eigen's matrix–vector kernel, as enter() does (q_i + the sum from 0 over k
  // ascending): the bits of lcp_velocity() on a dense M. A sparse M sums only its entries, so it
  // goes to lcp_velocity() like the run-time size.
  void write_w(const LcpProblem& problem, VectorView z, CapacityVector& w) const {
    if (N == 0 || problem.is_sparse) {
      write_lcp_velocity(problem, z, w);
      return;
    }
    w.resize(n());
    for (int i = 0; i < n(); ++i) {
      double sum = 0.0;
      for (int k = 0; k < n(); ++k) sum += M_(i, k) * z(k);
      w(i) = q_(i) + sum;
    }
  }

  // z from a fresh LU solve of B x = q: removes the rounding accumulated by the rank-one
  // updates of B⁻¹ over many pivots. Only valid once z0 has left the basis.
  Eigen::VectorXd z_refactored() const {
    Eigen::MatrixXd B(n(), n());
    for (int r = 0; r < n(); ++r) {
      const int v = basis_[r];
      B.col(r) = v < n() ? Eigen::VectorXd(Eigen::VectorXd::Unit(n(), v))
                         : Eigen::VectorXd(-M_.col(v - n()));
    }
    const Eigen::VectorXd x = B.partialPivLu().solve(q_);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n());
    for (int r = 0; r < n(); ++r) {
      if (basis_[r] >= n()) z(basis_[r] - n()) = x(r);
    }
    return z;
  }

 private:
  double* inverse_column(int k) const { return binv_ + static_cast<std::ptrdiff_t>(k) * n(); }

  // A fixed-size tableau's arrays are written in the pairs of rows its pivots read
  // (divide_pivot_row_in_pairs() says why): B⁻¹ = I, its row sizes 1 and x = q.
  void start_in_pairs() {
    constexpr int kPaired = kRowsInPairs<N>;
    for (int k = 0; k < N; ++k) {
      double* column = inverse_column(k);
      for (int i = 0; i < kPaired; i += 2) {
        store_pair(column + i, DoublePair{k == i ? 1.0 : 0.0, k == i + 1 ? 1.0 : 0.0});
      }
      if constexpr (N % 2 == 1) column[N - 1] = k == N - 1 ? 1.0 : 0.0;
    }
    fill_rows<kPaired>(row_size_, N, 1.0);
    copy_rows<kPaired>(q_.data(), N, x_);
  }

  // The pivot's first part for a row of a fixed-size tableau that lies in a pair of rows: row
  // `row` of B⁻¹ and x divided by p and c_row set to 0, as pivot() does it for other rows, but
  // each written as the pair of rows the update then reads (the other row divided by 1, which
  // leaves it as it is). A pair read right after a write of one of its halves cannot take the
  // value from the pending write and waits for it to reach the cache, at every pivot.
  void divide_pivot_row_in_pairs(int row, double p) {
    const int lane = row % 2;
    const int first = row - lane;
    const DoublePair divisor = lane == 0 ? DoublePair{p, 1.0} : DoublePair{1.0, p};
    for (int k = 0; k < n(); ++k) {
      double* pair = inverse_column(k) + first;
      store_pair(pair, load_pair(pair) / divisor);
      pivot_row_[k] = pair[lane];
    }
    store_pair(x_ + first, load_pair(x_ + first) / divisor);
    // The column is now the update's other factor.
    store_pair(column_ + first, with_lane_zeroed(load_pair(column_ + first), lane));
  }
  double inverse(int r, int k) const { return inverse_column(k)[r]; }

  // Lexicographic minimum among the tied_ rows in rows_ (narrowed in place), for the entering
  // column in column_.
  int lexicographic_minimum() {
    const double* c = column_;
    // Rounding of B⁻¹_rk / c_r: relative to the size of row r of B⁻¹ (its entries are
    // computed together), divided by c_r.
    for (int j = 0; j < tied_; ++j)
      rounding_[j] = kTieTolerance * row_size_[rows_[j]] / c[rows_[j]];
    for (int k = 0; k < n() && tied_ > 1; ++k) {
      // Each ratio divided once (the comparisons took three divisions per row).
      for (int j = 0; j < tied_; ++j) ratios_[j] = inverse(rows_[j], k) / c[rows_[j]];
      int best = 0;
      for (int j = 1; j < tied_; ++j)
        if (ratios_[j] < ratios_[best]) best = j;
      const double best_ratio = ratios_[best];
      const double best_rounding = rounding_[best];
      // Keep the tied rows, in order (a stable in-place filter).
      int kept = 0;
      for (int j = 0; j < tied_; ++j) {
        if (ties(ratios_[j], best_ratio, std::max(rounding_[j], best_rounding))) {
          rows_[kept] = rows_[j];
          rounding_[kept] = rounding_[j];
          ++kept;
        }
      }
      tied_ = kept;
    }
    return rows_[0];
  }

  const Eigen::MatrixXd& M_;
  const Eigen::VectorXd& q_;
  int n_;  // the size; n() is N where N is fixed
  // Parts of LemkeStorage::values.
  double* binv_;         // B⁻¹, n × n column-major
  double* row_size_;     // max_k |B⁻¹_rk| per row, kept by update_inverse_and_row_sizes()
  double* x_;            // x = B⁻¹ q
  double* column_;       // the entering column c = B⁻¹ a, then the update's other factor
  double* pivot_row_;    // the pivot row of B⁻¹ (a copy: the update overwrites B⁻¹)
  double q_size_ = 0.0;  // ‖q‖∞
  int* basis_;           // basis_[row] = variable basic in that row
  int* rows_;            // the tied rows of a ratio test
  double* rounding_;     // their rounding, in the lexicographic rule
  double* ratios_;       // their ratios B⁻¹_rk / c_r at one k of the lexicographic rule
  int tied_ = 0;         // how many rows rows_ holds
};

std::string variable_name(int variable, int n) {
  if (variable == 2 * n) return "z0";
  std::string name(1, variable < n ? 'w' : 'z');
  name += std::to_string(variable % n);
  return name;
}

/// `message` becomes the parts joined, in its own storage when that is large enough (a kept
/// result's message from an earlier solve): one allocation at most.
void set_message(std::string& message, std::initializer_list<std::string_view> parts) {
  std::size_t length = 0;
  for (const std::string_view part : parts) length += part.size();
  message.clear();
  message.reserve(length);
  for (const std::string_view part : parts) message += part;
}

/// The answer the basis holds: z, its w = M z + q and their residual, into `result`.
template <int N>
void write_answer(const LemkeTableau<N>& tableau, const LcpProblem& problem,
                  LcpMethodResult& result) {
  tableau.write_z(result.z);
  tableau.write_w(problem, result.z, result.w);
  result.residual = natural_map_residual(result.z, result.w);
  result.has_velocity = true;
}

/// Lemke's pivots on the tableau of N unknowns (LemkeTableau), into `result`.
template <int N>
void pivot_to_solution(const LcpProblem& problem, const Eigen::MatrixXd& M,
                       const SolverOptions& options, LemkeStorage& storage,
                       LcpMethodResult& result) {
  const int n = problem.size();
  LemkeTableau<N> tableau(M, problem.q, storage);
  if (options.max_iterations < 1) {
    result.z.setZero(n);
    result.status = SolverStatus::kMaxIterations;
    result.message = "no pivot allowed (max_iterations < 1)";
    return;
  }
  // First pivot: z0 enters.
  const int first = tableau.initial_row();
  int entering = tableau.complement(tableau.basic_variable(first));
  tableau.enter(tableau.z0());
  tableau.pivot(first, tableau.z0());
  result.iterations = 1;

  while (true) {
    if (result.iterations >= options.max_iterations) {
      tableau.write_z(result.z);
      result.status = SolverStatus::kMaxIterations;
      result.message = "pivot limit " + std::to_string(options.max_iterations) + " reached";
      return;
    }
    tableau.enter(entering);
    const int row = tableau.ratio_test(tableau.column_size(entering));
    if (row < 0) {
      write_answer(tableau, problem, result);
      // With the covering variable z0 down to rounding, the basis already holds a solution:
      // the ray is one of rounding-size entries, and the answer meets the tolerance as any
      // solver's answer does (moreau with lemke on disk_pile stopped at t = 0.273 on such a
      // ray with residual 5e-12).
      if (result.residual <= options.tolerance) {
        result.status = SolverStatus::kConverged;
        set_message(result.message, {"secondary ray after ", std::to_string(result.iterations),
                                     " pivots with z already a solution (residual ",
                                     output::number_text(result.residual), ")"});
        return;
      }
      result.status = SolverStatus::kRayTermination;
      set_message(result.message, {"secondary ray after ", std::to_string(result.iterations),
                                   " pivots: entering ", variable_name(entering, n),
                                   " is unbounded (no solution reachable by Lemke's method)"});
      return;
    }
    const int leaving = tableau.basic_variable(row);
    tableau.pivot(row, entering);
    ++result.iterations;
    if (leaving == tableau.z0()) break;
    if (!options.keep_going(result.iterations, std::numeric_limits<double>::quiet_NaN())) {
      tableau.write_z(result.z);
      result.status = SolverStatus::kStopped;
      result.message = "stopped after " + std::to_string(result.iterations) + " pivots";
      return;
    }
    entering = tableau.complement(leaving);
  }

  // Rounding accumulated over many pivots may leave the residual above tolerance: then try a
  // fresh factorisation of the final basis and keep whichever solution is better. The answer's
  // w and residual go back with it, so that the driver need not compute them again.
  write_answer(tableau, problem, result);
  if (!(result.residual <= options.tolerance)) {
    Eigen::VectorXd refined = tableau.z_refactored();
    if (refined.allFinite()) {
      CapacityVector refined_w = lcp_velocity(problem, refined);
      const double refined_residual = natural_map_residual(refined, refined_w);
      if (refined_residual < result.residual) {
        result.z = std::move(refined);
        result.w = std::move(refined_w);
        result.residual = refined_residual;
      }
    }
  }
  result.status = SolverStatus::kConverged;
}

using Pivoting = void (*)(const LcpProblem&, const Eigen::MatrixXd&, const SolverOptions&,
                          LemkeStorage&, LcpMethodResult&);

/// pivot_to_solution<n> for n = 0 … kFixedSizeLimit: the fixed size from 2 on, the run-time
/// size below.
template <int... n>
constexpr std::array<Pivoting, sizeof...(n)> pivoting_by_size(std::integer_sequence<int, n...>) {
  return {&pivot_to_solution<(n < 2 ? 0 : n)>...};
}
constexpr auto kPivotingBySize =
    pivoting_by_size(std::make_integer_sequence<int, kFixedSizeLimit + 1>{});

/// `pivoting` on the problem's M (a dense copy where M is sparse), in `storage`.
void pivot_on_dense_matrix(const LcpProblem& problem, const SolverOptions& options,
                           Pivoting pivoting, LemkeStorage& storage, LcpMethodResult& result) {
  Eigen::MatrixXd densified;
  if (problem.is_sparse) densified = Eigen::MatrixXd(problem.sparse_M);
  storage.reserve(problem.size());
  pivoting(problem, problem.is_sparse ? densified : problem.dense_M, options, storage, result);
}

}  // namespace

void solve_lemke(const LcpProblem& problem, const SolverOptions& options,
                 VectorView /*z_start: pivoting starts from w = q*/, LcpMethodResult& result) {
  const int n = problem.size();
  const ThreadKeptLease<LemkeStorage> lease(n <= kKeptSize);
  const Pivoting pivoting = n <= kFixedSizeLimit ? kPivotingBySize[n] : &pivot_to_solution<0>;
  pivot_on_dense_matrix(problem, options, pivoting, *lease, result);
}

void solve_lemke_at_run_time_size(const LcpProblem& problem, const SolverOptions& options,
                                  LcpMethodResult& result) {
  LemkeStorage storage;
  pivot_on_dense_matrix(problem, options, &pivot_to_solution<0>, storage, result);
}

}  // namespace impactbench::solvers::lcp
