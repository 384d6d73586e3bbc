#include "tests/support/solvers/lcp_test_problems.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace impactbench::solvers::lcp {
namespace {

Eigen::MatrixXd gaussian_matrix(int rows, int cols, double stddev, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, stddev);
  Eigen::MatrixXd A(rows, cols);
  for (int j = 0; j < cols; ++j) {
    for (int i = 0; i < rows; ++i) A(i, j) = normal(rng);
  }
  return A;
}

Eigen::VectorXd gaussian_vector(int n, std::mt19937_64& rng) {
  return gaussian_matrix(n, 1, 1.0, rng).col(0);
}

}  // namespace

LcpProblem murty_problem(int n) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) M(i, j) = 2.0;
  }
  return LcpProblem::dense(std::move(M), -Eigen::VectorXd::Ones(n));
}

LcpProblem reversed_murty_problem(int n) {
  LcpProblem p = murty_problem(n);
  p.dense_M.transposeInPlace();
  return p;
}

LcpProblem random_spd_problem(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::MatrixXd A = gaussian_matrix(n, n, 1.0 / std::sqrt(n), rng);
  Eigen::MatrixXd M = A.transpose() * A + Eigen::MatrixXd::Identity(n, n);
  return LcpProblem::dense(std::move(M), gaussian_vector(n, rng));
}

LcpProblem random_nonsymmetric_pd_problem(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::MatrixXd A = gaussian_matrix(n, n, 1.0 / std::sqrt(n), rng);
  const Eigen::MatrixXd K = gaussian_matrix(n, n, 1.0 / std::sqrt(n), rng);
  Eigen::MatrixXd M = A.transpose() * A + Eigen::MatrixXd::Identity(n, n) + K - K.transpose();
  return LcpProblem::dense(std::move(M), gaussian_vector(n, rng));
}

LcpProblem random_diagonally_dominant_problem(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> off(-1.0, 1.0);
  std::uniform_real_distribution<double> margin(0.5, 1.5);
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i) {
    double row_sum = 0.0;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      M(i, j) = off(rng);
      row_sum += std::abs(M(i, j));
    }
    M(i, i) = row_sum + margin(rng);
  }
  return LcpProblem::dense(std::move(M), gaussian_vector(n, rng));
}

LcpProblem degenerate_psd_problem(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> sign(-1, 1);
  std::uniform_int_distribution<int> magnitude(1, 3);
  std::uniform_int_distribution<int> kind(0, 3);
  // Integer data, so that equal ratios in Lemke's test are exactly equal.
  const int rows = std::max(1, n / 2);
  Eigen::MatrixXd B(rows, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < rows; ++i) B(i, j) = sign(rng);
  }
  // Column j + 1 repeats column j for j = 0, 3, 6, …: equal rows and columns of M = BᵀB.
  const auto is_twin = [](int j) { return j % 3 == 1; };
  for (int j = 1; j < n; ++j) {
    if (is_twin(j)) B.col(j) = B.col(j - 1);
  }
  Eigen::MatrixXd M = B.transpose() * B;

  // A complementary pair (z*, w*); twins copy their original, so q has equal entries.
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  std::vector<int> kinds(n);
  for (int i = 0; i < n; ++i) {
    kinds[i] = is_twin(i) ? kinds[i - 1] : kind(rng);
    if (kinds[i] == 0) z(i) = is_twin(i) ? z(i - 1) : magnitude(rng);
  }
  const Eigen::VectorXd Mz = M * z;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (kinds[i] == 1) w(i) = is_twin(i) ? w(i - 1) : magnitude(rng);
    // kind 2: z*_i = w*_i = 0 (a degenerate solution); kind 3: q_i = 0 where possible.
    if (kinds[i] == 3 && Mz(i) >= 0.0) w(i) = Mz(i);
  }
  Eigen::VectorXd q = w - Mz;
  return LcpProblem::dense(std::move(M), std::move(q));
}

LcpProblem random_sparse_contact_problem(int n, std::uint64_t seed, double delta, int window,
                                         ContactOrder order) {
  std::mt19937_64 rng(seed);
  const int bodies = std::max(2, n / 2);
  std::uniform_int_distribution<int> first(0, bodies - 2);
  std::uniform_int_distribution<int> gap(1, std::max(1, window));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<std::pair<int, int>> pairs(n);
  for (auto& [a, b] : pairs) {
    a = first(rng);
    b = std::min(bodies - 1, a + gap(rng));
  }
  if (order == ContactOrder::kByBody) std::sort(pairs.begin(), pairs.end());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(6 * static_cast<std::size_t>(n));
  for (int contact = 0; contact < n; ++contact) {
    for (int body : {pairs[contact].first, pairs[contact].second}) {
      for (int k = 0; k < 3; ++k) entries.emplace_back(contact, 3 * body + k, normal(rng));
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> J(n, 3 * bodies);
  J.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double, Eigen::RowMajor> identity(n, n);
  identity.setIdentity();
  Eigen::SparseMatrix<double, Eigen::RowMajor> M = J * J.transpose();
  M += delta * identity;
  M.makeCompressed();
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = uniform(rng);
  return LcpProblem::sparse(std::move(M), std::move(q));
}

}  // namespace impactbench::solvers::lcp
