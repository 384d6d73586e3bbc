#include "lib/engines/event_driven/local_contact_problem.hpp"

#include <stdexcept>

#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_methods.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr const char* kEnumeration = "enum";  // solvers/lcp: the exact small-problem solver

// The solver worked on the problem and did not solve it (a ray, a stall, the iteration limit),
// as opposed to refusing it (a zero diagonal for pgs, invalid or non-finite data): only the
// former are solved again by enumeration, so a solver that cannot take these problems at all
// still fails the run.
bool worked_without_converging(solvers::SolverStatus status) {
  using solvers::SolverStatus;
  return status == SolverStatus::kRayTermination || status == SolverStatus::kStalled ||
         status == SolverStatus::kMaxIterations;
}

// The drivers measure absolute residuals; scale the tolerance with the problem's q (velocities
// or accelerations), so that it means the same at every event.
solvers::SolverOptions solver_options(const EventDrivenOptions& options, const Eigen::VectorXd& q) {
  solvers::SolverOptions s;
  s.tolerance = options.solver_tolerance * (1.0 + (q.size() ? q.cwiseAbs().maxCoeff() : 0.0));
  s.max_iterations = options.solver_max_iterations;
  s.measure_seconds = false;  // solved at every impact and constrained right-hand side, never timed
  return s;
}

// Planar problems and spatial ones without Coulomb contacts: one LCP.
LocalContactSolution solve_as_lcp(const LocalContactProblem& p, const EventDrivenOptions& options) {
  const int n = p.num_contacts();
  const int b = p.block();
  std::vector<int> coulomb_index;  // contacts with friction unknowns (planar only)
  for (int i = 0; i < n; ++i)
    if (p.coulomb[static_cast<std::size_t>(i)]) coulomb_index.push_back(i);
  const int f = static_cast<int>(coulomb_index.size());
  const int size = n + 3 * f;
  // z = [r_n (n), r_t⁺ (f), r_t⁻ (f), β (f)].
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(size);
  auto col_n = [&](int j) { return b * j; };
  auto col_t = [&](int j) { return b * j + 1; };
  for (int i = 0; i < n; ++i) {
    q[i] = p.q[col_n(i)];
    for (int j = 0; j < n; ++j) M(i, j) = p.W(col_n(i), col_n(j));
    for (int k = 0; k < f; ++k) {
      const double wt = p.W(col_n(i), col_t(coulomb_index[static_cast<std::size_t>(k)]));
      M(i, n + k) = wt;
      M(i, n + f + k) = -wt;
    }
  }
  for (int k = 0; k < f; ++k) {
    const int c = coulomb_index[static_cast<std::size_t>(k)];
    const int rp = n + k, rm = n + f + k, rb = n + 2 * f + k;
    for (int j = 0; j < n; ++j) {
      M(rp, j) = p.W(col_t(c), col_n(j));
      M(rm, j) = -p.W(col_t(c), col_n(j));
    }
    for (int l = 0; l < f; ++l) {
      const double wt = p.W(col_t(c), col_t(coulomb_index[static_cast<std::size_t>(l)]));
      M(rp, n + l) = wt;
      M(rp, n + f + l) = -wt;
      M(rm, n + l) = -wt;
      M(rm, n + f + l) = wt;
    }
    M(rp, rb) = 1.0;
    M(rm, rb) = 1.0;
    q[rp] = p.q[col_t(c)];
    q[rm] = -p.q[col_t(c)];
    M(rb, c) = p.mu[c];
    M(rb, rp) = -1.0;
    M(rb, rm) = -1.0;
  }
  const solvers::LcpProblem lcp = solvers::LcpProblem::dense(M, q);
  const solvers::SolverOptions lcp_options = solver_options(options, q);
  auto result = solvers::solve_lcp(lcp, options.lcp_solver, lcp_options);
  LocalContactSolution out;
  if (worked_without_converging(result.status) && options.lcp_solver != kEnumeration &&
      size <= solvers::lcp::kMaxEnumerationSize) {
    auto enumerated = solvers::solve_lcp(lcp, kEnumeration, lcp_options);
    if (enumerated.converged()) {
      out.enumerated = true;
      enumerated.message = options.lcp_solver + " stopped (" +
                           std::string(solvers::to_string(result.status)) + " " + result.message +
                           "); solved by enumeration";
      result = std::move(enumerated);
    } else {
      result.message += "; enumeration: " + enumerated.message;
    }
  }
  out.status = result.status;
  out.message = result.message;
  out.r = Eigen::VectorXd::Zero(b * n);
  if (result.solution.size() == size) {
    for (int i = 0; i < n; ++i) out.r[col_n(i)] = result.solution[i];
    for (int k = 0; k < f; ++k)
      out.r[col_t(coulomb_index[static_cast<std::size_t>(k)])] =
          result.solution[n + k] - result.solution[n + f + k];
  }
  out.u = p.W * out.r + p.q;
  return out;
}

LocalContactSolution solve_as_friction_problem(const LocalContactProblem& p,
                                               const EventDrivenOptions& options) {
  Eigen::VectorXd mu = p.mu;
  for (int i = 0; i < p.num_contacts(); ++i)
    if (!p.coulomb[static_cast<std::size_t>(i)]) mu[i] = 0.0;  // μ = 0 forces r_t = 0
  const auto problem = solvers::FrictionProblem::dense(p.block(), p.W, p.q, mu);
  const auto result =
      solvers::solve_friction(problem, options.friction_solver, solver_options(options, p.q));
  LocalContactSolution out;
  out.status = result.status;
  out.message = result.message;
  out.r =
      result.solution.size() == p.q.size() ? result.solution : Eigen::VectorXd::Zero(p.q.size());
  out.u = p.W * out.r + p.q;
  return out;
}

}  // namespace

LocalContactSolution solve_local_contact_problem(const LocalContactProblem& problem,
                                                 const EventDrivenOptions& options) {
  const int m = problem.block() * problem.num_contacts();
  if (problem.W.rows() != m || problem.W.cols() != m || problem.q.size() != m ||
      problem.coulomb.size() != static_cast<std::size_t>(problem.num_contacts()))
    throw std::invalid_argument("event-driven local contact problem: inconsistent sizes");
  if (problem.num_contacts() == 0) {
    LocalContactSolution empty;
    empty.status = solvers::SolverStatus::kConverged;
    return empty;
  }
  bool any_coulomb = false;
  for (bool c : problem.coulomb) any_coulomb = any_coulomb || c;
  if (problem.tangent_dim == 1 || !any_coulomb) return solve_as_lcp(problem, options);
  return solve_as_friction_problem(problem, options);
}

}  // namespace impactbench::engines::event_driven
