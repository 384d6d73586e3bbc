#include "lib/engines/event_driven/mode_consistency.hpp"

#include "lib/engines/event_driven/local_contact_problem.hpp"
#include "solvers/common/solver_types.hpp"

namespace impactbench::engines::event_driven {
namespace {

struct Assembled {
  LocalContactProblem problem;
  Eigen::MatrixXd MinvG;  // nv x (1+d)n
  Eigen::VectorXd MinvF;
  std::vector<Eigen::VectorXd> slip;  // folded slip direction per included contact (or empty)
};

// Rows (1+d) per included contact: a = Jᵀ v̇ + drift; columns: the normal column g (w_n, or
// w_n − μ W_t s when the slip direction is known) and W_t.
Assembled assemble(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                   const std::vector<ModeCandidate>& candidates, const std::vector<int>& included,
                   const EventDrivenOptions& options) {
  const int nv = dynamics.nv();
  const int n = static_cast<int>(included.size());
  const int d = candidates.front().contact->tangent_dim();
  const int b = 1 + d;
  Assembled out;
  Eigen::MatrixXd A(b * n, nv), G(nv, b * n);
  Eigen::VectorXd drift(b * n);
  out.problem.tangent_dim = d;
  out.problem.mu.resize(n);
  out.problem.coulomb.assign(static_cast<std::size_t>(n), false);
  out.slip.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const ModeCandidate& c =
        candidates[static_cast<std::size_t>(included[static_cast<std::size_t>(k)])];
    const ContactFrame frame = ContactFrame::of(*c.contact, nv);
    const double mu = c.contact->friction;
    A.middleRows(b * k, b) = frame.J.transpose();
    G.middleCols(b * k, b) = frame.J;
    drift.segment(b * k, b) = frame.drift;
    out.problem.mu[k] = mu;
    const Eigen::VectorXd zeta_t = frame.J.rightCols(d).transpose() * v;
    Eigen::VectorXd s;
    if (c.hint == ModeCandidate::Hint::kForceSlip)
      s = c.forced_slip_direction;
    else if (zeta_t.norm() > options.velocity_tolerance)
      s = zeta_t.normalized();
    if (mu > 0.0 && s.size() == d) {
      G.col(b * k) -= mu * frame.J.rightCols(d) * s;  // B.37 folded into the normal column
      out.slip[static_cast<std::size_t>(k)] = s;
    } else {
      out.problem.coulomb[static_cast<std::size_t>(k)] = mu > 0.0;
    }
  }
  out.MinvG = dynamics.solve(G);
  out.MinvF = dynamics.solve(dynamics.free_force());
  out.problem.W = A * out.MinvG;
  out.problem.q = A * out.MinvF + drift;
  return out;
}

// One solve under the current hints: the contacts included (all but those preferred open),
// their problem and solution, and v̇.
struct Attempt {
  std::vector<int> included;
  Assembled assembled;
  LocalContactSolution solution;
  Eigen::VectorXd vdot;
};

// False when the solver fails (its message in `out`).
bool solve_attempt(const DynamicsAtState& dynamics, const Eigen::VectorXd& v,
                   const std::vector<ModeCandidate>& candidates, const EventDrivenOptions& options,
                   Attempt& attempt, ModeConsistencyResult& out) {
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (candidates[i].hint != ModeCandidate::Hint::kPreferOpen)
      attempt.included.push_back(static_cast<int>(i));
  if (attempt.included.empty()) {
    attempt.vdot = dynamics.solve(dynamics.free_force());
    return true;
  }
  attempt.assembled = assemble(dynamics, v, candidates, attempt.included, options);
  attempt.solution = solve_local_contact_problem(attempt.assembled.problem, options);
  if (attempt.solution.enumerated) ++out.enumerated;
  if (!attempt.solution.ok()) {
    out.ok = false;
    out.message = "acceleration-level contact problem: " +
                  std::string(solvers::to_string(attempt.solution.status)) + " " +
                  attempt.solution.message;
    return false;
  }
  attempt.vdot = attempt.assembled.MinvF + attempt.assembled.MinvG * attempt.solution.r;
  return true;
}

// Records the decisions of the contacts opened by their hint, and drops the hints the solution
// does not honour (penetration when opened, slip against the tendency when forced to slip);
// true when one was dropped.
bool drop_unhonoured_hints(std::vector<ModeCandidate>& candidates, const Attempt& attempt, int nv,
                           const EventDrivenOptions& options, ModeConsistencyResult& out) {
  const int d = candidates.front().contact->tangent_dim();
  const int b = 1 + d;
  const double accel_scale = 1.0 + attempt.vdot.cwiseAbs().maxCoeff();
  const double accel_hint_tol = options.complementarity_tolerance * accel_scale;
  bool dropped = false;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].hint != ModeCandidate::Hint::kPreferOpen) continue;
    const ContactFrame frame = ContactFrame::of(*candidates[i].contact, nv);
    const Eigen::VectorXd a = frame.J.transpose() * attempt.vdot + frame.drift;
    ModeDecision& decision = out.decisions[i];
    decision.mode = ContactMode::kOpen;
    decision.accel_n = a[0];
    decision.accel_t = a.tail(d);
    decision.lambda_t = Eigen::VectorXd::Zero(d);
    if (a[0] < -accel_hint_tol) {
      candidates[i].hint = ModeCandidate::Hint::kNone;
      dropped = true;
    }
  }
  for (std::size_t k = 0; k < attempt.included.size(); ++k) {
    auto& c = candidates[static_cast<std::size_t>(attempt.included[k])];
    if (c.hint != ModeCandidate::Hint::kForceSlip) continue;
    const Eigen::VectorXd at = attempt.solution.u.segment(b * static_cast<int>(k) + 1, d);
    if (at.dot(c.forced_slip_direction) < -accel_hint_tol) {
      c.hint = ModeCandidate::Hint::kNone;
      dropped = true;
    }
  }
  return dropped;
}

// The modes of the included contacts from the solution's forces and accelerations.
void decide_included(const std::vector<ModeCandidate>& candidates, const Attempt& attempt,
                     const EventDrivenOptions& options, ModeConsistencyResult& out) {
  const int d = candidates.front().contact->tangent_dim();
  const int b = 1 + d;
  const LocalContactSolution& solution = attempt.solution;
  const Eigen::VectorXd& problem_q = attempt.assembled.problem.q;
  const double force_scale = 1.0 + (solution.r.size() ? solution.r.cwiseAbs().maxCoeff() : 0.0);
  const double q_scale = 1.0 + (problem_q.size() ? problem_q.cwiseAbs().maxCoeff() : 0.0);
  const double force_tol = options.complementarity_tolerance * force_scale;
  const double accel_tol = options.complementarity_tolerance * q_scale;
  for (std::size_t k = 0; k < attempt.included.size(); ++k) {
    const auto i = static_cast<std::size_t>(attempt.included[k]);
    const int row = b * static_cast<int>(k);
    ModeDecision& decision = out.decisions[i];
    const double mu = candidates[i].contact->friction;
    decision.lambda_n = solution.r[row];
    decision.accel_n = solution.u[row];
    decision.accel_t = solution.u.segment(row + 1, d);
    const Eigen::VectorXd& s = attempt.assembled.slip[k];
    decision.lambda_t = s.size() == d ? Eigen::VectorXd(-mu * decision.lambda_n * s)
                                      : Eigen::VectorXd(solution.r.segment(row + 1, d));
    if (decision.lambda_n <= force_tol && decision.accel_n > accel_tol) {
      decision.mode = ContactMode::kOpen;
    } else if (s.size() == d) {
      decision.mode = ContactMode::kSlip;
      decision.slip_reference = s;
    } else if (mu == 0.0) {
      decision.mode = ContactMode::kSlip;  // frictionless: no tangential constraint
      decision.slip_reference = Eigen::VectorXd::Unit(d, 0);
    } else if (decision.accel_t.norm() > accel_tol) {
      decision.mode = ContactMode::kSlip;  // slips along its tendency, friction opposes it
      decision.slip_reference = decision.accel_t.normalized();
    } else {
      decision.mode = ContactMode::kStick;
    }
  }
}

}  // namespace

ModeConsistencyResult make_modes_consistent(const DynamicsAtState& dynamics,
                                            const Eigen::VectorXd& v,
                                            const std::vector<ModeCandidate>& candidates_in,
                                            const EventDrivenOptions& options) {
  ModeConsistencyResult out;
  out.decisions.resize(candidates_in.size());
  if (candidates_in.empty()) return out;
  std::vector<ModeCandidate> candidates = candidates_in;
  // A hint is kept only if the solution honours it; otherwise it is dropped and the problem
  // solved again.
  for (int attempt = 0; attempt <= static_cast<int>(candidates.size()); ++attempt) {
    Attempt solved;
    if (!solve_attempt(dynamics, v, candidates, options, solved, out)) return out;
    if (drop_unhonoured_hints(candidates, solved, dynamics.nv(), options, out)) continue;
    decide_included(candidates, solved, options, out);
    return out;
  }
  out.ok = false;
  out.message = "acceleration-level contact problem: no consistent modes for the guard hints";
  return out;
}

}  // namespace impactbench::engines::event_driven
