#include "tests/support/lib/event_complementarity_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace impactbench::test_support {

using engines::event_driven::ContactMode;

namespace {

// `from_rest` holds, for the contacts slipping with ζ_t = 0, the trial slip direction (planar ±1).
double violation_with(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                      const Eigen::VectorXd& v, const Eigen::VectorXd& u,
                      const std::map<model::ContactKey, ContactMode>& modes,
                      const std::map<std::size_t, double>& from_rest,
                      std::vector<std::size_t>* from_rest_contacts) {
  const int nv = system.num_velocities();
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(q, v, 1e3, contacts);
  const Eigen::MatrixXd M = Eigen::MatrixXd(system.mass_matrix(q));
  Eigen::VectorXd f = -system.bias_forces(q, v);
  if (system.num_inputs() > 0) f += system.input_matrix(q) * u;

  // Unknowns [v̇; λ]; closed contacts contribute rows J_iᵀ v̇ + drift = 0 for the constrained
  // components and force columns (slip: w_n − μ W_t s).
  struct Column {
    int contact;
    int component;
  };
  std::vector<Column> columns;
  std::vector<Eigen::VectorXd> force_dirs, constraint_rows;
  std::vector<double> rhs;
  std::vector<Eigen::VectorXd> slip_dirs(contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const auto it = modes.find(contacts[i].key);
    if (it == modes.end() || it->second == ContactMode::kOpen) continue;
    const auto& c = contacts[i];
    const int d = c.tangent_dim();
    const Eigen::VectorXd wn = c.normal_direction(nv);
    const Eigen::MatrixXd Wt = c.tangent_directions(nv);
    Eigen::VectorXd normal_force = wn;
    if (it->second == ContactMode::kSlip && c.friction > 0.0) {
      const Eigen::VectorXd zeta_t = Wt.transpose() * v;
      if (zeta_t.norm() > 1e-7) {
        slip_dirs[i] = zeta_t.normalized();
      } else if (d == 1) {
        if (from_rest_contacts) from_rest_contacts->push_back(i);
        const auto r = from_rest.find(i);
        slip_dirs[i] = Eigen::VectorXd::Constant(1, r == from_rest.end() ? 1.0 : r->second);
      }
      if (slip_dirs[i].size() == d) normal_force -= c.friction * Wt * slip_dirs[i];
    }
    columns.push_back({static_cast<int>(i), 0});
    force_dirs.push_back(normal_force);
    constraint_rows.push_back(wn);
    rhs.push_back(-c.normal_drift);
    if (it->second == ContactMode::kStick) {
      for (int k = 0; k < d; ++k) {
        columns.push_back({static_cast<int>(i), 1 + k});
        force_dirs.push_back(Wt.col(k));
        constraint_rows.push_back(Wt.col(k));
        rhs.push_back(-c.tangent_drift[k]);
      }
    }
  }
  const int m = static_cast<int>(columns.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nv + m, nv + m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(nv + m);
  K.topLeftCorner(nv, nv) = M;
  b.head(nv) = f;
  for (int j = 0; j < m; ++j) {
    K.block(0, nv + j, nv, 1) = -force_dirs[static_cast<std::size_t>(j)];
    K.block(nv + j, 0, 1, nv) = constraint_rows[static_cast<std::size_t>(j)].transpose();
    b[nv + j] = rhs[static_cast<std::size_t>(j)];
  }
  const Eigen::VectorXd x = K.completeOrthogonalDecomposition().solve(b);
  const Eigen::VectorXd vdot = x.head(nv);
  const double force_scale = 1.0 + f.cwiseAbs().maxCoeff();
  const double accel_scale = 1.0 + M.ldlt().solve(f).cwiseAbs().maxCoeff();

  double violation = (K * x - b).norm() / force_scale;
  double stick_n = 0.0, stick_t = 0.0, stick_mu = 0.0;
  for (int j = 0; j < m; ++j) {
    const auto ci = static_cast<std::size_t>(columns[static_cast<std::size_t>(j)].contact);
    const auto& c = contacts[ci];
    const double lambda = x[nv + j];
    const ContactMode mode = modes.at(c.key);
    if (columns[static_cast<std::size_t>(j)].component == 0) {
      violation = std::max(violation, -lambda / force_scale);
      if (mode == ContactMode::kStick) {
        stick_n += lambda;
        stick_mu = c.friction;
      }
      if (mode == ContactMode::kSlip && c.friction > 0.0 && from_rest.count(ci)) {
        // Slipping from rest: the friction −μλ_n s must oppose the tangential acceleration.
        const Eigen::VectorXd at = c.tangent_directions(nv).transpose() * vdot + c.tangent_drift;
        violation = std::max(violation, -at.dot(slip_dirs[ci]) / accel_scale);
      }
    } else if (mode == ContactMode::kStick) {
      stick_t += std::abs(lambda);
    }
  }
  violation = std::max(violation, (stick_t - stick_mu * stick_n) / force_scale);
  for (const auto& c : contacts) {
    const auto it = modes.find(c.key);
    if (it != modes.end() && it->second != ContactMode::kOpen) continue;
    const double zeta_n = c.relative_velocity(v)[0];
    if (c.gap > 1e-8 || std::abs(zeta_n) > 1e-7) continue;
    const double an = c.normal_direction(nv).dot(vdot) + c.normal_drift;
    violation = std::max(violation, -an / accel_scale);
    violation = std::max(violation, -c.gap);
  }
  return violation;
}

}  // namespace

double acceleration_complementarity_violation(
    const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
    const Eigen::VectorXd& v, const Eigen::VectorXd& u,
    const std::map<model::ContactKey, ContactMode>& modes) {
  std::vector<std::size_t> from_rest;
  double best = violation_with(system, q, v, u, modes, {}, &from_rest);
  if (from_rest.empty()) return best;
  best = std::numeric_limits<double>::infinity();
  // Planar slip from rest: the better of the two directions for each such contact.
  const std::size_t k = from_rest.size();
  for (std::size_t mask = 0; mask < (std::size_t{1} << k); ++mask) {
    std::map<std::size_t, double> dirs;
    for (std::size_t j = 0; j < k; ++j) dirs[from_rest[j]] = (mask >> j) & 1 ? -1.0 : 1.0;
    best = std::min(best, violation_with(system, q, v, u, modes, dirs, nullptr));
  }
  return best;
}

}  // namespace impactbench::test_support
