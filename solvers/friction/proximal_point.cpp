#include "solvers/friction/proximal_point.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/common/thread_kept.hpp"
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

namespace {

struct ProximalScratch {
  std::vector<LocalMatrix> blocks;
  std::vector<AlartCurnierParameters> steps;
  CapacityVector best;
  CapacityVector velocity;  // u at the iterate, for the residual of a formed W
};

}  // namespace

Outcome run_proximal_point(const FrictionProblem& problem, const SolverOptions& options,
                           const ProximalSweep& sweep, CapacityVector& r, double entry_residual,
                           const ProximalResidual& residual_at, const ProximalReset& reset,
                           const ProximalSteps& steps_of) {
  constexpr double kMaxOmega = 1.9;
  constexpr double kMinOmega = 1e-10;
  constexpr double kDivergence = 10.0;
  constexpr double kShrink = 0.7;
  constexpr double kGrow = 1.2;
  constexpr double kSlowProgress = 0.95;
  // Kept per thread between solves (a time stepper solves one problem a step), so that a solve
  // whose problem keeps its size allocates nothing; lent to one solve at a time.
  const ThreadKeptLease<ProximalScratch> scratch;
  std::vector<LocalMatrix>& blocks = scratch->blocks;
  std::vector<AlartCurnierParameters>& steps = scratch->steps;
  CapacityVector& best = scratch->best;
  const auto steps_from_diagonal_blocks = [&](std::vector<AlartCurnierParameters>& out) {
    diagonal_blocks(problem, blocks);
    out.clear();
    for (const LocalMatrix& block : blocks) {
      if (!(block(0, 0) > 0.0)) return false;
      out.push_back(alart_curnier_parameters(block));
    }
    return true;
  };
  if (!(steps_of ? steps_of(steps) : steps_from_diagonal_blocks(steps)))
    return nonpositive_normal_diagonal();
  for (AlartCurnierParameters& step : steps) {
    step.rho_n *= options.rho_scale;
    step.rho_t *= options.rho_scale;
  }
  double omega = options.proximal_omega;
  // friction_residual(problem, r_k) to the bit, with u in kept storage and the divisor formed
  // once per solve instead of once per sweep.
  CapacityVector& velocity = scratch->velocity;
  const double scale = residual_at ? 1.0 : residual_scale(problem);
  const auto residual_of = [&](VectorView r_k) {
    if (residual_at) return residual_at(r_k);
    write_contact_velocity(problem, r_k, velocity);
    return friction_residual(problem, r_k, velocity, scale);
  };
  // The driver's residual at the entry r is this one's to the bit (the same u = W r + q).
  double previous_residual = std::isnan(entry_residual) ? residual_of(r) : entry_residual;
  double best_residual = previous_residual;
  best = r;
  Outcome outcome;
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    sweep(problem, steps, omega, r);
    const double residual = residual_of(r);
    if (residual <= options.tolerance) {
      outcome.status = SolverStatus::kConverged;
      return outcome;
    }
    if (!(residual <= kDivergence * best_residual)) {  // divergence (or NaN): back to the best
      r = best;
      if (reset) reset(r);
      omega *= 0.5;
      if (omega < kMinOmega) {
        outcome.status = SolverStatus::kStalled;
        outcome.message = "proximal parameter exhausted (omega < 1e-10)";
        return outcome;
      }
      previous_residual = best_residual;
      continue;
    }
    if (residual > previous_residual) {
      omega = std::max(kMinOmega, kShrink * omega);  // growth: damp
    } else if (residual > kSlowProgress * previous_residual) {
      omega = std::min(kGrow * omega, kMaxOmega);  // stall: larger steps
    }
    if (residual < best_residual) {
      best_residual = residual;
      best = r;
    }
    previous_residual = residual;
    if (!options.keep_going(outcome.iterations, residual)) {
      r = best;
      outcome.status = SolverStatus::kStopped;
      outcome.message = "stopped by the caller";
      return outcome;
    }
  }
  r = best;
  // The status (kMaxIterations, Outcome's default) says it: no message, so that a solve with a
  // fixed sweep count, stopped here at every step, allocates nothing for it.
  outcome.iterations = options.max_iterations;
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
