#include "tests/support/solvers/random_friction_problem.hpp"

#include <random>
#include <vector>

#include <Eigen/Geometry>

namespace impactbench::solvers {

Eigen::VectorXd contact_jacobian_row(const Eigen::VectorXd& direction,
                                     const Eigen::VectorXd& lever_arm) {
  if (direction.size() == 2) {
    return Eigen::Vector3d(direction(0), direction(1),
                           -lever_arm(1) * direction(0) + lever_arm(0) * direction(1));
  }
  Eigen::VectorXd row(6);
  row << direction, Eigen::Vector3d(lever_arm).cross(Eigen::Vector3d(direction));
  return row;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> delassus_from_jacobian(
    const Eigen::SparseMatrix<double>& jacobian, const Eigen::SparseMatrix<double>& inverse_mass) {
  const Eigen::SparseMatrix<double> jacobian_transpose = jacobian.transpose();
  Eigen::SparseMatrix<double, Eigen::RowMajor> w = jacobian * inverse_mass * jacobian_transpose;
  w.makeCompressed();
  return w;
}

namespace {

// H and A by contact blocks, one per body (dofs velocities) that a contact's rows of H touch,
// bodies ascending: H's rows on the body (d × dofs), then A's columns (dofs × d), column-major.
FactorBlocks factor_blocks_by_body(const Eigen::SparseMatrix<double>& h,
                                   const Eigen::SparseMatrix<double>& a, int d, int dofs) {
  const Eigen::MatrixXd dense_h(h);
  const Eigen::MatrixXd dense_a(a);
  FactorBlocks blocks;
  blocks.velocities = static_cast<int>(h.cols());
  blocks.contact_start.push_back(0);
  for (int i = 0; i < static_cast<int>(h.rows()) / d; ++i) {
    for (int body = 0; body < static_cast<int>(h.cols()) / dofs; ++body) {
      const Eigen::MatrixXd rows = dense_h.block(i * d, body * dofs, d, dofs);
      if (rows.isZero(0.0)) continue;
      const Eigen::MatrixXd columns = dense_a.block(body * dofs, i * d, dofs, d);
      blocks.first_velocity.push_back(body * dofs);
      blocks.size.push_back(dofs);
      blocks.offset.push_back(static_cast<int>(blocks.values.size()));
      blocks.values.insert(blocks.values.end(), rows.data(), rows.data() + rows.size());
      blocks.values.insert(blocks.values.end(), columns.data(), columns.data() + columns.size());
    }
    blocks.contact_start.push_back(static_cast<int>(blocks.first_velocity.size()));
  }
  return blocks;
}

}  // namespace

FrictionProblem random_friction_problem(const RandomFrictionSpec& spec) {
  const int d = spec.dimension;
  const int space = d;  // ambient dimension equals the contact dimension (2 or 3)
  const int dofs = d == 2 ? 3 : 6;
  std::mt19937 generator(spec.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> positive(0.5, 2.0);
  std::uniform_int_distribution<int> body_choice(-1, spec.bodies - 1);  // −1: the ground

  // Per-body inverse mass: a random SPD block (a rotated inertia), so M is SPD, not diagonal.
  std::vector<Eigen::Triplet<double>> mass_entries;
  for (int b = 0; b < spec.bodies; ++b) {
    Eigen::MatrixXd root = Eigen::MatrixXd::Identity(dofs, dofs);
    for (int r = 0; r < dofs; ++r) {
      for (int c = 0; c < dofs; ++c) root(r, c) += 0.3 * unit(generator);
    }
    const Eigen::MatrixXd inverse =
        root * root.transpose() / positive(generator) + 0.1 * Eigen::MatrixXd::Identity(dofs, dofs);
    for (int r = 0; r < dofs; ++r) {
      for (int c = 0; c < dofs; ++c)
        mass_entries.emplace_back(b * dofs + r, b * dofs + c, inverse(r, c));
    }
  }
  Eigen::SparseMatrix<double> inverse_mass(spec.bodies * dofs, spec.bodies * dofs);
  inverse_mass.setFromTriplets(mass_entries.begin(), mass_entries.end());

  std::vector<Eigen::Triplet<double>> jacobian_entries;
  Eigen::VectorXd q(spec.contacts * d);
  Eigen::VectorXd mu(spec.contacts);
  std::uniform_real_distribution<double> friction(0.1, 1.0);
  std::uniform_real_distribution<double> approach(-1.0, 0.3);
  for (int i = 0; i < spec.contacts; ++i) {
    // Random orthonormal frame, normal first.
    Eigen::MatrixXd frame(space, space);
    if (space == 2) {
      Eigen::Vector2d normal(unit(generator), unit(generator));
      normal = normal.norm() > 1e-3 ? normal.normalized() : Eigen::Vector2d::UnitY();
      frame << normal, Eigen::Vector2d(-normal.y(), normal.x());
    } else {
      Eigen::Matrix3d random;
      for (int c = 0; c < 9; ++c) random(c) = unit(generator);
      frame = Eigen::HouseholderQR<Eigen::Matrix3d>(random).householderQ();
    }
    int first = body_choice(generator);
    int second = body_choice(generator);
    if (first < 0 && second < 0) first = i % spec.bodies;
    if (first == second) second = -1;
    for (const auto& [body, sign] : {std::pair{first, 1.0}, std::pair{second, -1.0}}) {
      if (body < 0) continue;
      Eigen::VectorXd lever(space);
      for (int c = 0; c < space; ++c) lever(c) = 0.5 * unit(generator);
      for (int k = 0; k < d; ++k) {
        const Eigen::VectorXd row = contact_jacobian_row(frame.col(k), lever);
        for (int c = 0; c < dofs; ++c)
          jacobian_entries.emplace_back(i * d + k, body * dofs + c, sign * row(c));
      }
    }
    q(i * d) = approach(generator);
    for (int k = 1; k < d; ++k) q(i * d + k) = unit(generator);
    mu(i) = friction(generator);
  }
  Eigen::SparseMatrix<double> jacobian(spec.contacts * d, spec.bodies * dofs);
  jacobian.setFromTriplets(jacobian_entries.begin(), jacobian_entries.end());
  if (spec.factored) {
    Eigen::SparseMatrix<double> a = inverse_mass * jacobian.transpose();
    FactorBlocks blocks;
    if (spec.factor_blocks) blocks = factor_blocks_by_body(jacobian, a, d, dofs);
    FrictionProblem problem =
        FrictionProblem::factored(d, Eigen::SparseMatrix<double, Eigen::RowMajor>(jacobian),
                                  std::move(a), std::move(q), std::move(mu));
    problem.factor_blocks = std::move(blocks);
    return problem;
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> w = delassus_from_jacobian(jacobian, inverse_mass);
  if (spec.sparse) return FrictionProblem::sparse(d, std::move(w), std::move(q), std::move(mu));
  return FrictionProblem::dense(d, Eigen::MatrixXd(w), std::move(q), std::move(mu));
}

}  // namespace impactbench::solvers
