#include "solvers/friction/proximal_point.hpp"

#include <algorithm>

#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_residual.hpp"

namespace impactbench::solvers::friction_detail {

LocalVector proximal_update(double mu, const AlartCurnierParameters& rho, double omega,
                            const LocalVector& r, const LocalVector& u) {
  const int t = static_cast<int>(r.size()) - 1;
  LocalVector next(r.size());
  next(0) = std::max(0.0, r(0) - omega * rho.rho_n * u(0));
  next.tail(t) = project_on_disk(mu * next(0), r.tail(t) - omega * rho.rho_t * u.tail(t));
  return next;
}

Outcome run_proximal_point(const FrictionProblem& problem, const SolverOptions& options,
                           const ProximalSweep& sweep, Eigen::VectorXd& r) {
  constexpr double kMaxOmega = 1.9;
  constexpr double kMinOmega = 1e-10;
  std::vector<AlartCurnierParameters> steps;
  steps.reserve(static_cast<std::size_t>(problem.num_contacts()));
  for (const LocalMatrix& block : diagonal_blocks(problem)) {
    if (!(block(0, 0) > 0.0)) {
      return {0, SolverStatus::kSingular, "a diagonal entry W_nn is not positive"};
    }
    steps.push_back(alart_curnier_parameters(block));
  }
  double omega = 1.0;
  double residual = friction_residual(problem, r);
  Eigen::VectorXd previous = r;
  Outcome outcome;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    previous = r;
    sweep(problem, steps, omega, r);
    const double next_residual = friction_residual(problem, r);
    if (!(next_residual <= residual)) {  // divergence (or NaN): undo and shrink ω
      r = previous;
      omega *= 0.5;
      if (omega < kMinOmega) {
        outcome.status = SolverStatus::kStalled;
        outcome.message = "proximal parameter exhausted (omega < 1e-10)";
        return outcome;
      }
      continue;
    }
    if (next_residual > 0.9 * residual) omega = std::min(1.5 * omega, kMaxOmega);
    residual = next_residual;
    if (residual <= options.tolerance) {
      outcome.status = SolverStatus::kConverged;
      return outcome;
    }
  }
  outcome.iterations = options.max_iterations;
  outcome.message = "iteration limit reached";
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
