#include "lib/engines/event_driven/impact_map.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "lib/engines/event_driven/local_contact_problem.hpp"
#include "solvers/common/solver_types.hpp"

namespace impactbench::engines::event_driven {

namespace {

// single_contact_impact's intermediate matrices, kept per thread: the map runs at every impact,
// and these few-entry matrices were a dozen heap allocations of each call. The same
// expressions fill them, so the results are the same to the bit.
struct SingleImpactScratch {
  ContactFrame frame;
  Eigen::MatrixXd MinvJ, D;
  Eigen::FullPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd target_shift, stick, residual, s, column, Minv_column;
};

}  // namespace

ImpactResult single_contact_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v_minus,
                                   const model::Contact<double>& contact, double e,
                                   const EventDrivenOptions& options) {
  thread_local SingleImpactScratch w;
  const int nv = dynamics.nv();
  const int d = contact.tangent_dim();
  const double mu = contact.friction;
  w.frame.assign(contact, nv);
  const Eigen::MatrixXd& J = w.frame.J;
  dynamics.solve(J, w.MinvJ);
  w.D.noalias() = J.transpose() * w.MinvJ;  // B.30
  ContactImpulse c;
  c.zeta_before = J.transpose() * v_minus;
  const double zeta_n = c.zeta_before[0];

  w.target_shift.setZero(1 + d);
  w.target_shift[0] = e * zeta_n;
  w.lu.compute(w.D);
  w.stick = w.lu.solve(-(c.zeta_before + w.target_shift));
  const Eigen::VectorXd& stick = w.stick;
  c.gamma = mu * mu * stick[0] * stick[0] - stick.tail(d).squaredNorm();  // B.25
  // D Λ + ζ⁻ + shift, summed in that order.
  w.residual.noalias() = w.D * stick;
  w.residual += c.zeta_before;
  w.residual += w.target_shift;
  ImpactResult out;
  if (mu > 0.0 && c.gamma >= 0.0 &&
      w.residual.norm() <= options.stick_impulse_residual * (1.0 + c.zeta_before.norm())) {
    c.map = ContactMode::kStick;
    c.impulse = stick;
  } else if (mu > 0.0 && d > 1) {
    // In space the sliding direction turns during the impact; the impulse-level Coulomb law
    // (friction opposite to the post-impact sliding velocity) is solved exactly instead.
    ImpactResult coulomb = simultaneous_impact(dynamics, v_minus, {&contact}, {e}, options);
    if (coulomb.ok) {
      coulomb.contacts.front().map = ContactMode::kSlip;
      coulomb.contacts.front().gamma = c.gamma;
    }
    return coulomb;
  } else {
    c.map = ContactMode::kSlip;
    // B.21 takes the direction of the pre-impact sliding velocity ζ_t⁻. When the Delassus
    // matrix couples normal and tangent (D_nt ≠ 0, e.g. a box corner) the normal impulse can
    // reverse the sliding, and friction along ε(ζ_t⁻) would then push with the post-impact
    // sliding instead of against it. Saturating the stick impulse's direction instead,
    // Λ_t = μ Λ_n ε(Λ_t^stick), is the impulse-level Coulomb law (the post-impact sliding is
    // opposite to it whenever D_nn + μ |D_nt| > 0), and makes the map continuous at Γ = 0.
    Eigen::VectorXd& s = w.s;
    s.setZero(d);
    if (mu > 0.0) {
      const auto zeta_t = c.zeta_before.tail(d);
      if (stick.tail(d).norm() > 0.0)
        s = -stick.tail(d).normalized();
      else if (zeta_t.norm() > 0.0)
        s = zeta_t.normalized();
    }
    w.column.noalias() = J.col(0) - mu * J.rightCols(d) * s;
    w.Minv_column.resize(nv);
    dynamics.solve(w.column, w.Minv_column);
    const double denominator = J.col(0).dot(w.Minv_column);
    if (!(denominator > 0.0)) {
      out.ok = false;
      out.message = "slip impact map: w_nᵀM⁻¹(w_n − μW_t s) ≤ 0 at contact '" + contact.name +
                    "' (friction too large for a Painlevé-free impact)";
      return out;
    }
    c.impulse.resize(1 + d);
    c.impulse[0] = -(1.0 + e) * zeta_n / denominator;
    c.impulse.tail(d) = -mu * c.impulse[0] * s;  // B.21 with the direction above
  }
  out.v_plus = v_minus + w.MinvJ * c.impulse;  // B.19/B.22
  c.zeta_after = J.transpose() * out.v_plus;
  out.contacts.push_back(std::move(c));
  return out;
}

ImpactResult simultaneous_impact(const DynamicsAtState& dynamics, const Eigen::VectorXd& v_minus,
                                 const std::vector<const model::Contact<double>*>& contacts,
                                 const std::vector<double>& restitution,
                                 const EventDrivenOptions& options) {
  const int nv = dynamics.nv();
  const int n = static_cast<int>(contacts.size());
  const int d = contacts.front()->tangent_dim();
  const int b = 1 + d;
  Eigen::MatrixXd J(nv, b * n);
  LocalContactProblem problem;
  problem.tangent_dim = d;
  problem.mu.resize(n);
  problem.coulomb.assign(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    J.middleCols(b * i, b) = ContactFrame::of(*contacts[static_cast<std::size_t>(i)], nv).J;
    problem.mu[i] = contacts[static_cast<std::size_t>(i)]->friction;
    problem.coulomb[static_cast<std::size_t>(i)] = problem.mu[i] > 0.0;
  }
  const Eigen::MatrixXd MinvJ = dynamics.solve(J);
  problem.W = J.transpose() * MinvJ;
  const Eigen::VectorXd zeta_before = J.transpose() * v_minus;
  problem.q = zeta_before;
  for (int i = 0; i < n; ++i)
    problem.q[b * i] +=
        restitution[static_cast<std::size_t>(i)] * std::min(zeta_before[b * i], 0.0);
  const LocalContactSolution solution = solve_local_contact_problem(problem, options);
  ImpactResult out;
  if (!solution.ok()) {
    out.ok = false;
    out.message =
        "impulse-level contact problem: " + std::string(solvers::to_string(solution.status)) + " " +
        solution.message;
    return out;
  }
  out.enumerated = solution.enumerated;
  out.v_plus = v_minus + MinvJ * solution.r;
  const Eigen::VectorXd zeta_after = J.transpose() * out.v_plus;
  for (int i = 0; i < n; ++i) {
    ContactImpulse c;
    c.impulse = solution.r.segment(b * i, b);
    c.zeta_before = zeta_before.segment(b * i, b);
    c.zeta_after = zeta_after.segment(b * i, b);
    c.map = (problem.mu[i] > 0.0 && c.zeta_after.tail(d).norm() <= options.velocity_tolerance)
                ? ContactMode::kStick
                : ContactMode::kSlip;
    c.gamma = std::numeric_limits<double>::quiet_NaN();
    out.contacts.push_back(std::move(c));
  }
  return out;
}

}  // namespace impactbench::engines::event_driven
