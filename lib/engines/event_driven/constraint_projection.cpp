#include "lib/engines/event_driven/constraint_projection.hpp"

#include <vector>

#include <Eigen/Dense>

namespace impactbench::engines::event_driven {
namespace {

// δ minimising δᵀMδ with Jᵀδ = −r (least squares when redundant).
Eigen::VectorXd least_norm_correction(const RunContext& run, const Eigen::VectorXd& q,
                                      const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  const Eigen::MatrixXd MinvJ = run.mass_factor(q)->solve(J);
  const Eigen::MatrixXd D = J.transpose() * MinvJ;
  return -MinvJ * D.completeOrthogonalDecomposition().solve(r);
}

// Two Newton passes on the gaps h_n(q) = 0 of the closed contacts; false when none is closed.
bool project_positions(const RunContext& run, const ContactModes& modes, Eigen::VectorXd& q,
                       const Eigen::VectorXd& v) {
  if (modes.all_open()) return false;  // no contact can be closed: skip the contact search
  std::vector<model::Contact<double>> contacts;
  for (int pass = 0; pass < 2; ++pass) {
    run.find_contacts(q, v, contacts);
    const auto closed = modes.closed_among(contacts);
    if (closed.empty()) return false;
    Eigen::MatrixXd Wn(run.nv, static_cast<Eigen::Index>(closed.size()));
    Eigen::VectorXd gaps(Wn.cols());
    for (std::size_t i = 0; i < closed.size(); ++i) {
      Wn.col(static_cast<Eigen::Index>(i)) = closed[i].contact->normal_direction(run.nv);
      gaps[static_cast<Eigen::Index>(i)] = closed[i].contact->gap;
    }
    q = run.system.integrate_position(q, least_norm_correction(run, q, Wn, gaps), 1.0);
  }
  return true;
}

void project_velocities(const RunContext& run, const ContactModes& modes, const Eigen::VectorXd& q,
                        Eigen::VectorXd& v) {
  std::vector<model::Contact<double>> contacts;
  run.find_contacts(q, v, contacts);
  const auto closed = modes.closed_among(contacts);
  std::vector<Eigen::VectorXd> rows;
  for (const auto& c : closed) {
    rows.push_back(c.contact->normal_direction(run.nv));
    if (c.mode == ContactMode::kStick) {
      const Eigen::MatrixXd Wt = c.contact->tangent_directions(run.nv);
      for (Eigen::Index k = 0; k < Wt.cols(); ++k) rows.push_back(Wt.col(k));
    }
  }
  Eigen::MatrixXd A(run.nv, static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) A.col(static_cast<Eigen::Index>(i)) = rows[i];
  v += least_norm_correction(run, q, A, A.transpose() * v);
}

}  // namespace

void project_onto_closed_constraints(const RunContext& run, const ContactModes& modes,
                                     Eigen::VectorXd& q, Eigen::VectorXd& v) {
  if (project_positions(run, modes, q, v)) project_velocities(run, modes, q, v);
}

}  // namespace impactbench::engines::event_driven
