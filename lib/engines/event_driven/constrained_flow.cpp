#include "lib/engines/event_driven/constrained_flow.hpp"

#include <Eigen/Dense>

#include "lib/model/slip_direction.hpp"

namespace impactbench::engines::event_driven {

ContactFrame ContactFrame::of(const model::Contact<double>& contact, int nv) {
  ContactFrame frame;
  frame.assign(contact, nv);
  return frame;
}

void ContactFrame::assign(const model::Contact<double>& contact, int nv) {
  const int d = contact.tangent_dim();
  J.resize(nv, 1 + d);
  contact.write_normal_direction(J.col(0));
  contact.write_tangent_directions(J.rightCols(d));
  drift.resize(1 + d);
  drift[0] = contact.normal_drift;
  drift.tail(d) = contact.tangent_drift;
}

Eigen::VectorXd slip_direction(const Eigen::VectorXd& zeta_t, const Eigen::VectorXd& reference,
                               double blend_speed) {
  if (zeta_t.size() == 1) return reference;
  return model::smoothed_slip_direction<double>(zeta_t, reference, blend_speed);
}

namespace {

// Among the solutions λ0 + N y of D λ = b, the one with the least weighted norm, tangential
// components weighted by 1/(μ λ_n) (see the header).
Eigen::VectorXd spread_indeterminate_forces(const Eigen::MatrixXd& N,
                                            const Eigen::VectorXd& lambda0,
                                            const std::vector<ClosedContact>& closed,
                                            double capacity_floor) {
  Eigen::VectorXd lambda = lambda0;
  for (int pass = 0; pass < 2; ++pass) {
    const double scale = lambda.cwiseAbs().maxCoeff() + 1e-300;
    Eigen::VectorXd weight = Eigen::VectorXd::Constant(lambda.size(), 1.0 / scale);
    int row = 0;
    for (const auto& c : closed) {
      const int d = c.contact->tangent_dim();
      if (c.mode == ContactMode::kStick) {
        const double cap = std::max(c.contact->friction * lambda[row], capacity_floor * scale);
        weight.segment(row + 1, d).setConstant(1.0 / cap);
        row += 1 + d;
      } else {
        row += 1;
      }
    }
    const Eigen::MatrixXd NtW = N.transpose() * weight.asDiagonal();
    const Eigen::VectorXd y = (NtW * N).ldlt().solve(-NtW * lambda0);
    lambda = lambda0 + N * y;
  }
  return lambda;
}

}  // namespace

FlowSolution solve_constrained_flow(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                                    const std::vector<ClosedContact>& closed,
                                    const EventDrivenOptions& options) {
  FlowWorkspace work;
  FlowSolution out;
  solve_constrained_flow(dynamics, v, closed, options, work, out);
  return out;
}

void solve_constrained_flow(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                            const std::vector<ClosedContact>& closed,
                            const EventDrivenOptions& options, FlowWorkspace& work,
                            FlowSolution& out) {
  const int nv = dynamics.nv();
  out.ok = true;
  int m = 0;
  for (const auto& c : closed)
    m += c.mode == ContactMode::kStick ? 1 + c.contact->tangent_dim() : 1;
  if (m == 0) {
    out.vdot.resize(nv);
    dynamics.solve(dynamics.free_force(), out.vdot);
    out.forces.clear();
    return;
  }
  Eigen::MatrixXd &A = work.A, &G = work.G;
  Eigen::VectorXd& drift = work.drift;
  A.resize(m, nv);
  G.resize(nv, m);
  drift.resize(m);
  std::vector<Eigen::VectorXd>& slip_dirs = work.slip_dirs;
  slip_dirs.resize(closed.size());
  const Eigen::MatrixXd& J = work.frame.J;
  int row = 0;
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const auto& c = closed[i];
    const int d = c.contact->tangent_dim();
    work.frame.assign(*c.contact, nv);
    A.row(row) = J.col(0).transpose();
    G.col(row) = J.col(0);
    drift[row] = work.frame.drift[0];
    if (c.mode == ContactMode::kSlip && c.contact->friction > 0.0) {
      work.zeta_t.noalias() = J.rightCols(d).transpose() * v;
      slip_dirs[i] = slip_direction(work.zeta_t, c.slip_reference, options.velocity_tolerance);
      G.col(row) -= c.contact->friction * J.rightCols(d) * slip_dirs[i];
    }
    ++row;
    if (c.mode == ContactMode::kStick) {
      A.middleRows(row, d) = J.rightCols(d).transpose();
      G.middleCols(row, d) = J.rightCols(d);
      drift.segment(row, d) = work.frame.drift.tail(d);
      row += d;
    }
  }
  const Eigen::MatrixXd& MinvG = work.MinvG;
  const Eigen::VectorXd& MinvF = work.MinvF;
  dynamics.solve(G, work.MinvG);
  work.MinvF.resize(nv);
  dynamics.solve(dynamics.free_force(), work.MinvF);
  work.D.noalias() = A * MinvG;
  work.b = -(A * MinvF + drift);
  const Eigen::MatrixXd& D = work.D;
  const Eigen::VectorXd& b = work.b;

  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>& cod = work.cod;
  cod.setThreshold(options.flow_rank_threshold);
  cod.compute(D);
  Eigen::VectorXd& lambda = work.lambda;
  lambda = cod.solve(b);
  const double residual = (D * lambda - b).norm();
  if (!(residual <= options.flow_residual_tolerance * (1.0 + b.norm() + D.norm() * lambda.norm())))
    out.ok = false;
  if (cod.rank() < m) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(D);
    lu.setThreshold(options.flow_rank_threshold);
    if (lu.rank() < m)
      lambda =
          spread_indeterminate_forces(lu.kernel(), lambda, closed, options.friction_capacity_floor);
  }
  out.vdot = MinvF + MinvG * lambda;
  out.forces.resize(closed.size());
  row = 0;
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const auto& c = closed[i];
    const int d = c.contact->tangent_dim();
    auto& force = out.forces[i];
    force.lambda_n = lambda[row++];
    if (c.mode == ContactMode::kStick) {
      force.lambda_t = lambda.segment(row, d);
      row += d;
    } else if (c.contact->friction > 0.0) {
      force.lambda_t = -c.contact->friction * force.lambda_n * slip_dirs[i];
    } else {
      force.lambda_t.setZero(d);
    }
  }
}

}  // namespace impactbench::engines::event_driven
