#include "solvers/friction/lcp_conversion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>

#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {
namespace {

/// Tangential directions d_j as columns (1 × 2 planar, 2 × k spatial).
Eigen::MatrixXd tangent_directions(int dimension, int cone_facets) {
  if (dimension == 2) return Eigen::RowVector2d(1.0, -1.0);
  Eigen::MatrixXd directions(2, cone_facets);
  for (int j = 0; j < cone_facets; ++j) {
    const double angle = 2.0 * std::numbers::pi * j / cone_facets;
    directions.col(j) << std::cos(angle), std::sin(angle);
  }
  return directions;
}

}  // namespace

FrictionLcp friction_to_lcp(const FrictionProblem& problem, int cone_facets) {
  if (problem.dimension == 3 && cone_facets < 3) {
    throw std::invalid_argument("faceted friction cone needs at least 3 facets, got " +
                                std::to_string(cone_facets));
  }
  const int d = problem.dimension;
  const int contacts = problem.num_contacts();
  const Eigen::MatrixXd directions = tangent_directions(d, cone_facets);
  FrictionLcp conversion;
  conversion.directions = static_cast<int>(directions.cols());
  const int m = conversion.variables_per_contact();
  const int k = conversion.directions;

  std::vector<Eigen::Triplet<double>> t_entries;
  std::vector<Eigen::Triplet<double>> c_entries;
  for (int i = 0; i < contacts; ++i) {
    t_entries.emplace_back(i * d, i * m, 1.0);
    const int beta = i * m + k + 1;
    c_entries.emplace_back(beta, i * m, problem.mu(i));
    for (int j = 0; j < k; ++j) {
      for (int c = 0; c < d - 1; ++c)
        t_entries.emplace_back(i * d + 1 + c, i * m + 1 + j, directions(c, j));
      c_entries.emplace_back(i * m + 1 + j, beta, 1.0);
      c_entries.emplace_back(beta, i * m + 1 + j, -1.0);
    }
  }
  conversion.to_impulse.resize(problem.size(), contacts * m);
  conversion.to_impulse.setFromTriplets(t_entries.begin(), t_entries.end());
  Eigen::SparseMatrix<double> coupling(contacts * m, contacts * m);
  coupling.setFromTriplets(c_entries.begin(), c_entries.end());

  const Eigen::SparseMatrix<double>& t = conversion.to_impulse;
  const Eigen::SparseMatrix<double> t_transpose = t.transpose();
  Eigen::VectorXd q = t_transpose * problem.q;
  if (problem.is_sparse) {
    const Eigen::SparseMatrix<double> w = problem.sparse_W;
    Eigen::SparseMatrix<double, Eigen::RowMajor> matrix = t_transpose * w * t + coupling;
    conversion.lcp = LcpProblem::sparse(std::move(matrix), std::move(q));
  } else {
    const Eigen::MatrixXd w_t = problem.dense_W * t;
    Eigen::MatrixXd matrix = t_transpose * w_t;
    matrix += Eigen::MatrixXd(coupling);
    conversion.lcp = LcpProblem::dense(std::move(matrix), std::move(q));
  }
  return conversion;
}

Eigen::VectorXd impulse_from_lcp(const FrictionLcp& conversion, VectorView z) {
  return conversion.to_impulse * z;
}

Eigen::VectorXd lcp_point_from_impulse(const FrictionProblem& problem,
                                       const FrictionLcp& conversion, VectorView r) {
  const int d = problem.dimension;
  const int k = conversion.directions;
  const int m = conversion.variables_per_contact();
  const CapacityVector u = contact_velocity(problem, r);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(problem.num_contacts() * m);
  const double sector = 2.0 * std::numbers::pi / k;
  for (int i = 0; i < problem.num_contacts(); ++i) {
    z(i * m) = std::max(0.0, r(i * d));
    double beta = 0.0;
    if (d == 2) {
      z(i * m + 1) = std::max(0.0, r(i * d + 1));
      z(i * m + 2) = std::max(0.0, -r(i * d + 1));
      beta = std::abs(u(i * d + 1));
    } else {
      const Eigen::Vector2d r_t = r.segment<2>(i * d + 1);
      const Eigen::Vector2d u_t = u.segment<2>(i * d + 1);
      double angle = std::atan2(r_t.y(), r_t.x());
      if (angle < 0.0) angle += 2.0 * std::numbers::pi;
      const int first = std::min(k - 1, static_cast<int>(angle / sector));
      const int second = (first + 1) % k;
      Eigen::Matrix2d span;
      span << std::cos(first * sector), std::cos(second * sector), std::sin(first * sector),
          std::sin(second * sector);
      const Eigen::Vector2d weights = span.inverse() * r_t;
      z(i * m + 1 + first) = std::max(0.0, weights(0));
      z(i * m + 1 + second) = std::max(0.0, weights(1));
      for (int j = 0; j < k; ++j) {
        beta = std::max(beta, -(std::cos(j * sector) * u_t.x() + std::sin(j * sector) * u_t.y()));
      }
    }
    z(i * m + k + 1) = beta;
  }
  return z;
}

}  // namespace impactbench::solvers
