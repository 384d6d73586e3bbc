#include "common/friction_piles.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "tests/support/solvers/random_friction_problem.hpp"

namespace impactbench::bench {
namespace {

struct Body {
  Eigen::Vector3d center;  // z = 0 for disks
  double radius = 1.0;
};

/// Orthonormal frame with the given normal first (columns), in 2 or 3 dimensions.
Eigen::MatrixXd contact_frame(const Eigen::Vector3d& normal, int dimension) {
  if (dimension == 2) {
    Eigen::MatrixXd frame(2, 2);
    frame << normal.x(), -normal.y(), normal.y(), normal.x();
    return frame;
  }
  const Eigen::Vector3d helper =
      std::abs(normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = normal.cross(helper).normalized();
  Eigen::MatrixXd frame(3, 3);
  frame << normal, t1, normal.cross(t1);
  return frame;
}

}  // namespace

solvers::FrictionProblem pile_problem(int dimension, int contacts, bool dense, std::uint32_t seed) {
  const int d = dimension;
  const int dofs = d == 2 ? 3 : 6;
  const int up = d == 2 ? 1 : 2;  // y up in the plane, z up in space
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::bernoulli_distribution touches(0.5);
  std::uniform_real_distribution<double> friction(0.2, 0.8);

  // Lattice: columns (× depth in space) × rows; about 1.5 (planar) or 2 (spatial) contacts per
  // body.
  const int bodies = std::max(1, static_cast<int>(contacts / (d == 2 ? 1.5 : 2.0)));
  const int width =
      std::max(1, static_cast<int>(std::lround(std::pow(bodies, d == 2 ? 0.5 : 1.0 / 3.0))));
  const int layer = d == 2 ? width : width * width;
  std::vector<Body> pile;
  for (int b = 0; pile.size() < static_cast<std::size_t>(bodies) || b % layer != 0; ++b) {
    Body body;
    body.radius = 1.0 + jitter(generator);
    const int row = b / layer;
    const int x = b % width;
    const int y = (b % layer) / width;
    body.center = Eigen::Vector3d(2.0 * x + jitter(generator), 2.0 * y + jitter(generator), 0.0);
    body.center(up) = 2.0 * row + 1.0;
    pile.push_back(body);
  }
  const int n_bodies = static_cast<int>(pile.size());

  struct Contact {
    int a, b;  // b = −1: the ground
    Eigen::Vector3d normal;
  };
  std::vector<Contact> list;
  const auto neighbour = [&](int a, int b) {
    Eigen::Vector3d normal =
        pile[static_cast<std::size_t>(a)].center - pile[static_cast<std::size_t>(b)].center;
    list.push_back({a, b, normal.normalized()});
  };
  for (int a = 0; a < n_bodies && static_cast<int>(list.size()) < contacts; ++a) {
    const int row = a / layer;
    const int x = a % width;
    const int y = (a % layer) / width;
    if (row == 0) {
      list.push_back({a, -1, d == 2 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ()});
    } else {
      neighbour(a, a - layer);
    }
    if (x > 0 && touches(generator)) neighbour(a, a - 1);
    if (d == 3 && y > 0 && touches(generator)) neighbour(a, a - width);
  }

  std::vector<Eigen::Triplet<double>> inverse_mass;
  Eigen::VectorXd free_velocity(n_bodies * dofs);
  for (int b = 0; b < n_bodies; ++b) {
    const double r = pile[static_cast<std::size_t>(b)].radius;
    const double mass =
        d == 2 ? std::numbers::pi * r * r : 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double inertia = (d == 2 ? 0.5 : 0.4) * mass * r * r;
    for (int k = 0; k < dofs; ++k) {
      const bool rotational = d == 2 ? k == 2 : k >= 3;
      inverse_mass.emplace_back(b * dofs + k, b * dofs + k, 1.0 / (rotational ? inertia : mass));
      free_velocity(b * dofs + k) = 0.3 * unit(generator);
    }
    free_velocity(b * dofs + (d == 2 ? 1 : 2)) = -1.0 - 0.5 * (b / layer);  // higher falls faster
  }
  Eigen::SparseMatrix<double> m_inverse(n_bodies * dofs, n_bodies * dofs);
  m_inverse.setFromTriplets(inverse_mass.begin(), inverse_mass.end());

  const int n_contacts = static_cast<int>(list.size());
  std::vector<Eigen::Triplet<double>> jacobian_entries;
  Eigen::VectorXd mu(n_contacts);
  for (int i = 0; i < n_contacts; ++i) {
    const Contact& contact = list[static_cast<std::size_t>(i)];
    const Eigen::MatrixXd frame = contact_frame(contact.normal, d);
    for (const auto& [body, sign] : {std::pair{contact.a, 1.0}, std::pair{contact.b, -1.0}}) {
      if (body < 0) continue;
      // The contact point lies on each surface along the normal (a above/right of b).
      const Eigen::Vector3d lever =
          -sign * pile[static_cast<std::size_t>(body)].radius * contact.normal;
      for (int k = 0; k < d; ++k) {
        const Eigen::VectorXd row = solvers::contact_jacobian_row(frame.col(k), lever.head(d));
        for (int c = 0; c < dofs; ++c)
          jacobian_entries.emplace_back(i * d + k, body * dofs + c, sign * row(c));
      }
    }
    mu(i) = friction(generator);
  }
  Eigen::SparseMatrix<double> jacobian(n_contacts * d, n_bodies * dofs);
  jacobian.setFromTriplets(jacobian_entries.begin(), jacobian_entries.end());
  Eigen::SparseMatrix<double, Eigen::RowMajor> w =
      solvers::delassus_from_jacobian(jacobian, m_inverse);
  Eigen::VectorXd q = jacobian * free_velocity;
  if (dense)
    return solvers::FrictionProblem::dense(d, Eigen::MatrixXd(w), std::move(q), std::move(mu));
  return solvers::FrictionProblem::sparse(d, std::move(w), std::move(q), std::move(mu));
}

const solvers::FrictionProblem& cached_pile_problem(int dimension, int contacts) {
  static std::map<std::pair<int, int>, std::unique_ptr<solvers::FrictionProblem>> cache;
  auto& slot = cache[{dimension, contacts}];
  if (!slot) {
    slot = std::make_unique<solvers::FrictionProblem>(
        pile_problem(dimension, contacts, contacts <= 500));
  }
  return *slot;
}

}  // namespace impactbench::bench
