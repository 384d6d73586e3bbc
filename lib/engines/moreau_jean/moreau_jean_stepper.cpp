#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "lib/engines/moreau_jean/cold_restart.hpp"
#include "lib/engines/moreau_jean/delassus_assembly.hpp"
#include "lib/engines/moreau_jean/free_motion.hpp"
#include "lib/engines/step_count.hpp"
#include "lib/model/contact_prefetch.hpp"
#include "lib/model/contact_storage.hpp"
#include "lib/output/message_text.hpp"
#include "solvers/common/all_finite.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

// `name_of(c)` gives a contact's name (the candidates may be unnamed, lagrangian_system.hpp).
template <typename NameOf>
void check_contact(const model::Contact<double>& c, int tangent_dim, const NameOf& name_of) {
  // The contact's name is put into a message only when a check fails (this runs per candidate).
  const auto who = [&] { return "contact '" + name_of(c) + "'"; };
  if (!std::isfinite(c.gap)) throw std::invalid_argument(who() + " has a non-finite gap");
  if (!(c.friction >= 0.0) || !std::isfinite(c.friction))
    throw std::invalid_argument(who() + " has friction μ = " + output::number_text(c.friction) +
                                ", must be finite and >= 0");
  if (!(c.restitution >= 0.0 && c.restitution <= 1.0))
    throw std::invalid_argument(who() + " has restitution e = " +
                                output::number_text(c.restitution) + ", must be in [0, 1]");
  if (c.tangent_dim() != tangent_dim)
    throw std::invalid_argument(who() + " has " + std::to_string(c.tangent_dim()) +
                                " tangent directions, the system " + std::to_string(tangent_dim));
}

void sorted_keys(const std::vector<model::Contact<double>>& contacts,
                 std::vector<model::ContactKey>& keys) {
  keys.clear();
  for (const auto& c : contacts) keys.push_back(c.key);
  std::sort(keys.begin(), keys.end());
}

// Previous impulses of the contacts with the same key, zero for new contacts. `previous_keys`
// files the previous step's candidates, its active ones first: the impulses of positions below
// previous_impulses.size(). A key first filed past them was not active (a key is found at its
// first position).
void gather_warm_start(const model::ContactKeyIndex& previous_keys,
                       const std::vector<std::array<double, 3>>& previous_impulses,
                       std::span<const model::ContactKey> active, int dim,
                       solvers::CapacityVector& warm) {
  warm.resize(static_cast<Eigen::Index>(active.size()) * dim);  // each entry written below
  const auto previous_active = static_cast<int>(previous_impulses.size());
  int hint = 0;  // the active contacts come in about the previous step's order
  for (std::size_t i = 0; i < active.size(); ++i) {
    const int found = previous_keys.find(active[i], hint);
    const bool was_active = found >= 0 && found < previous_active;
    if (was_active) hint = found + 1;
    for (int k = 0; k < dim; ++k)
      warm(static_cast<Eigen::Index>(i) * dim + k) =
          was_active
              ? previous_impulses[static_cast<std::size_t>(found)][static_cast<std::size_t>(k)]
              : 0.0;
  }
}

std::string failure_message(const std::string& solver, double t,
                            const solvers::SolverResult& result) {
  return "contact solver '" + solver + "' at t = " + output::number_text(t) + ": " +
         std::string(solvers::to_string(result.status)) + ", residual " +
         output::number_text(result.residual) + " after " + std::to_string(result.iterations) +
         " iterations" + (result.message.empty() ? "" : " (" + result.message + ")");
}

template <typename NameOf>
std::vector<ContactImpulse> impulse_records(std::span<const model::Contact<double>> active,
                                            const Eigen::MatrixXd& zeta_before,
                                            solvers::VectorView r, const Eigen::VectorXd& v_next,
                                            int d, const NameOf& name_of) {
  const int dim = 1 + d;
  std::vector<ContactImpulse> records;
  records.reserve(active.size());
  for (std::size_t i = 0; i < active.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i) * dim;
    ContactImpulse ci;
    ci.key = active[i].key;
    ci.name = name_of(active[i]);
    ci.gap = active[i].gap;
    ci.point = active[i].point;
    ci.normal = active[i].normal;
    ci.friction = active[i].friction;
    ci.restitution = active[i].restitution;
    ci.r_n = r(row);
    ci.r_t = r.segment(row + 1, d);
    ci.u_before = zeta_before.col(static_cast<Eigen::Index>(i));
    ci.u_after = active[i].relative_velocity(v_next);
    records.push_back(std::move(ci));
  }
  return records;
}

}  // namespace

namespace {
MoreauJeanOptions validated(MoreauJeanOptions options) {
  validate(options);
  return options;
}
}  // namespace

MoreauJeanStepper::MoreauJeanStepper(const model::LagrangianSystem<double>& system,
                                     MoreauJeanOptions options)
    : system_(system), options_(validated(std::move(options))), solver_(options_.solver) {}

void MoreauJeanStepper::check_state(const MoreauJeanState& s) const {
  if (s.q.size() != system_.num_positions())
    throw std::invalid_argument("Moreau–Jean: q has size " + std::to_string(s.q.size()) +
                                ", the system " + std::to_string(system_.num_positions()));
  if (s.v.size() != system_.num_velocities())
    throw std::invalid_argument("Moreau–Jean: v has size " + std::to_string(s.v.size()) +
                                ", the system " + std::to_string(system_.num_velocities()));
  if (!solvers::all_finite(s.q) || !solvers::all_finite(s.v) || !std::isfinite(s.t))
    throw std::invalid_argument("Moreau–Jean: the state (t, q, v) is not finite");
}

Eigen::VectorXd MoreauJeanStepper::input_at(const InputFunction& input, double t) const {
  const int nu = system_.num_inputs();
  if (!input) {
    if (nu == 0) return Eigen::VectorXd();
    throw std::invalid_argument("Moreau–Jean: the system has " + std::to_string(nu) +
                                " inputs but no input function was given");
  }
  Eigen::VectorXd u = input(t);
  if (u.size() != nu)
    throw std::invalid_argument("Moreau–Jean: input u(t) has size " + std::to_string(u.size()) +
                                ", the system " + std::to_string(nu));
  if (!u.allFinite())
    throw std::invalid_argument("Moreau–Jean: input u(" + output::number_text(t) +
                                ") is not finite");
  return u;
}

void MoreauJeanStepper::find_candidates(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                        const Eigen::VectorXd& v_free, double h) {
  const double margin = options_.contact_margin;
  // The contacts within the margin at the end of the step if no impulse acted.
  const double theta = options_.theta;
  v_blend_ = (1.0 - theta) * v + theta * v_free;
  const Eigen::VectorXd& v_blend = v_blend_;
  // One search where the system bounds its contacts' motion: a contact within the margin at the
  // predicted state, or active by the rule gap + γ h ζ(v) ≤ activation_tolerance (γ ≤ 1), has
  // a gap at q below the margin (and the tolerance) plus what |v| or |v_blend| lets its bodies
  // travel in h.
  speed_bound_ = v.cwiseAbs().cwiseMax(v_blend.cwiseAbs());
  candidates_named_ = false;
  if (system_.find_reachable_contacts(q, v, speed_bound_, h, margin + options_.activation_tolerance,
                                      candidates_))
    return;
  candidates_named_ = true;
  system_.find_contacts(system_.integrate_position(q, v_blend, h), v_blend, margin, predicted_);
  // Their gap at q_k, estimated back along the motion, sizes the search at q_k (one search
  // instead of a margin search and a wider one); it doubles until every predicted contact is
  // found (the estimate is linear, the geometry need not be).
  double reach = 0.0;
  for (const auto& c : predicted_)
    reach = std::max(reach, c.gap - h * c.relative_velocity(v_blend)(0));
  double wider = reach > 0.0 ? std::max(2.0 * margin, reach + margin) : margin;
  std::vector<model::ContactKey>& found = candidate_keys_;
  const auto missing = [&](const model::Contact<double>& c) {
    return !std::binary_search(found.begin(), found.end(), c.key);
  };
  for (int attempt = 0; attempt < 64 && std::isfinite(wider); ++attempt) {
    system_.find_contacts(q, v, wider, candidates_);
    sorted_keys(candidates_, found);
    if (std::none_of(predicted_.begin(), predicted_.end(), missing)) return;
    wider = std::max(wider, 2.0 * margin) * 2.0;
  }
}

StepReport MoreauJeanStepper::step(MoreauJeanState& state, const InputFunction& input) {
  return step(state, input, options_.dt);
}

StepReport MoreauJeanStepper::step(MoreauJeanState& state, const InputFunction& input, double h) {
  check_state(state);
  if (!(h > 0.0) || !std::isfinite(h))
    throw std::invalid_argument("Moreau–Jean: step size must be > 0, got " +
                                output::number_text(h));
  StepReport report;
  StepStatistics& stats = report.statistics;
  stats.t = state.t + h;
  stats.energy_before = energy_at_start(state);

  // The stages in the order they run (the header's numbering is the method's: 2, 1, 3, 4).
  const FreeMotion& free = free_motion_stage(state, input, h);
  const std::span<const model::Contact<double>> active =
      contact_selection_stage(state.q, state.v, free.free_velocity, h, stats);
  v_next_ = free.free_velocity;
  // r of a step without active contacts is empty; a solve swaps its answer in (the storage of
  // both kept for the next step's).
  if (active.empty()) r_.resize(0);
  if (!active.empty() && !contact_solve_stage(active, state, free, report)) return report;
  advance_stage(state, active, h, report);
  return report;
}

// Stage 2 of the method, first in time: the smooth part (free_motion.hpp), v_free and Â⁻¹ (M⁻¹
// with explicit forces). It does not depend on the contacts; the candidate search needs the
// predicted motion.
const FreeMotion& MoreauJeanStepper::free_motion_stage(const MoreauJeanState& state,
                                                       const InputFunction& input, double h) {
  const double theta = options_.theta;
  const Eigen::VectorXd u_theta =
      system_.num_inputs() > 0 ? input_at(input, state.t + theta * h) : Eigen::VectorXd();
  compute_free_motion(system_, state.q, state.v, u_theta, h, options_, &constant_mass_inverse_,
                      free_motion_);
  return free_motion_;
}

// Stage 1: the candidates and the active set (predicted gap rule). The active candidates are
// copied to the front of candidates_, in their order; their ζ_k kept by column in zeta_before_.
// A copy, not a swap: each slot keeps its own heap storage (contact_storage.hpp), where swaps
// traded it between the slots at every step, so that a large pile's slots came to point all
// over the heap and every loop over them (evaluation, selection, assembly) jumped through it.
// The slots after the active ones are not read again this step.
std::span<const model::Contact<double>> MoreauJeanStepper::contact_selection_stage(
    const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& v_free, double h,
    StepStatistics& stats) {
  const int d = system_.tangent_dim();
  find_candidates(q, v, v_free, h);
  stats.candidate_contacts = static_cast<int>(candidates_.size());
  const double gamma = activation_horizon(options_);
  // Grown only (the columns past the active ones are not read): resized to every new candidate
  // count, it reallocated at most steps.
  if (zeta_before_.rows() != 1 + d ||
      zeta_before_.cols() < static_cast<Eigen::Index>(candidates_.size()))
    zeta_before_.resize(1 + d, static_cast<Eigen::Index>(candidates_.size()));
  selected_keys_.resize(candidates_.size());
  std::size_t num_active = 0;
  int late_hint = 0;  // the candidates come in about the previous step's order
  for (std::size_t k = 0; k < candidates_.size(); ++k) {
    model::prefetch_contact_storage<double>(candidates_, k);
    model::Contact<double>& c = candidates_[k];
    check_contact(c, d,
                  [this](const model::Contact<double>& named) { return contact_name(named); });
    selected_keys_[k] = c.key;
    stats.max_penetration = std::max(stats.max_penetration, -c.gap);
    if (c.gap < -options_.activation_tolerance) {
      const int found = previous_candidates_.find(c.key, late_hint);
      if (found < 0)
        ++stats.late_contacts;
      else
        late_hint = found + 1;
    }
    auto zeta = zeta_before_.col(static_cast<Eigen::Index>(num_active));
    zeta.setZero();
    c.add_relative_velocity(v, zeta);
    if (c.gap + gamma * h * zeta(0) <= options_.activation_tolerance) {
      if (k != num_active) {
        model::copy_keeping_storage(c, candidates_[num_active]);
        std::swap(selected_keys_[num_active], selected_keys_[k]);
      }
      ++num_active;
    }
  }
  stats.active_contacts = static_cast<int>(num_active);
  return {candidates_.data(), num_active};
}

// Stage 3: the contact impulses r and v_next = v_free + Â⁻¹ Jᵀ r, with the failure policy:
// false when the step must not advance (the report then says why).
bool MoreauJeanStepper::contact_solve_stage(std::span<const model::Contact<double>> active,
                                            const MoreauJeanState& state, const FreeMotion& free,
                                            StepReport& report) {
  const int d = system_.tangent_dim();
  const int dim = 1 + d;
  const int m = static_cast<int>(active.size());
  assemble_delassus(active, d, free.inverse(), state.v, free.free_velocity,
                    options_.dense_delassus_max_rows,
                    /*factored=*/solver_.sweeps_factored_delassus(), delassus_);
  gather_warm_start(previous_candidates_, warm_start_impulses_, active_keys(active.size()), dim,
                    warm_);
  solvers::SolverOptions solver_options;
  solver_options.tolerance = options_.tolerance;
  solver_options.max_iterations = options_.max_iterations;
  solver_options.cone_facets = options_.cone_facets;
  solve_with_cold_restart(delassus_.problem, solver_, solver_options, warm_, options_.cold_restart,
                          result_);
  const solvers::SolverResult& result = result_;
  StepStatistics& stats = report.statistics;
  stats.solver_iterations = result.iterations;
  stats.residual = result.residual;
  stats.solve_seconds = result.seconds;
  stats.solver_status = result.status;
  stats.converged = result.converged();
  // The driver reports kConvergedFaceted when the faceted LCP was solved but its solution is
  // not one of the disk problem (friction_solvers.cpp): the faceted model's answer, accepted.
  if (d == 2 && solver_.solves_through_lcp()) {
    stats.faceted_cone = true;
    stats.converged = stats.converged || result.status == solvers::SolverStatus::kConvergedFaceted;
  }
  // kWarn continues only past an iterate the solver worked on (iteration limit, stall); a
  // problem it rejected (singular, invalid, non-finite, ray termination) ends the run.
  const bool usable = (result.status == solvers::SolverStatus::kMaxIterations ||
                       result.status == solvers::SolverStatus::kStalled) &&
                      result.solution.size() == m * dim && result.solution.allFinite();
  if (!stats.converged) {
    // Kept for the message, which is formed only when asked for (a failed solve can be the
    // common case, e.g. with a fixed sweep count).
    failed_solve_.t = state.t;
    failed_solve_.result.status = result.status;
    failed_solve_.result.residual = result.residual;
    failed_solve_.result.iterations = result.iterations;
    failed_solve_.result.message = result.message;
    report.message_text.set_form(
        [this] { return failure_message(options_.solver, failed_solve_.t, failed_solve_.result); });
    if (options_.on_failure == OnFailure::kStop || !usable) {
      report.advanced = false;
      r_.resize(0);  // no impulses: the step did not advance
      return false;
    }
  }
  r_.swap(result_.solution);  // the answer's storage, not a copy
  // M⁻¹ Jᵀ r into zeros, then added: as Eigen adds a product it forms itself (the same bits).
  // The solve's A r at this r (nsgs's last check, or the driver's u after prox-gs) is that
  // product to the bit (the same function forms both), so it is added instead of formed again.
  const bool handed_over =
      delassus_.problem.is_factored && result_.factored_velocity.size() == v_next_.size();
  if (!handed_over) delassus_.write_impulse_velocity(r_, impulse_velocity_);
  v_next_ += handed_over ? result_.factored_velocity : impulse_velocity_;
  return true;
}

// Stage 4: positions with the θ-blended velocity, the bookkeeping for the next step (late
// contacts, warm starts, the impulses formed on demand), then the state moves to t + h.
void MoreauJeanStepper::advance_stage(MoreauJeanState& state,
                                      std::span<const model::Contact<double>> active, double h,
                                      StepReport& report) {
  const double theta = options_.theta;
  const int d = system_.tangent_dim();
  v_blend_ = (1.0 - theta) * state.v + theta * v_next_;
  system_.write_integrated_position(state.q, v_blend_, h, q_next_);
  if (!q_next_.allFinite() || !v_next_.allFinite()) {
    report.advanced = false;
    report.message_text.set_value("the state became non-finite at t = " +
                                  output::number_text(state.t));
    return;
  }
  previous_candidates_.build(selected_keys_);
  // Formed on first use from the step's active contacts, ζ_k, r and v_{k+1}, which stay until
  // the next step.
  active_ = active;
  report.impulse_records.set_form([this] {
    return impulse_records(active_, zeta_before_, r_, v_next_, system_.tangent_dim(),
                           [this](const model::Contact<double>& c) { return contact_name(c); });
  });
  warm_start_impulses_.resize(active.size());
  for (std::size_t i = 0; i < active.size(); ++i)
    for (int k = 0; k <= d; ++k)
      warm_start_impulses_[i][static_cast<std::size_t>(k)] =
          r_(static_cast<Eigen::Index>(i) * (1 + d) + k);

  state.t += h;
  state.q.swap(q_next_);  // q_next_ keeps q_k's storage for the next step
  state.v = v_next_;
  report.statistics.energy_after = system_.energy(state.q, state.v);
  produced_.q = state.q;
  produced_.v = state.v;
  produced_.energy = report.statistics.energy_after;
  produced_.known = true;
}

std::string MoreauJeanStepper::contact_name(const model::Contact<double>& c) const {
  if (candidates_named_) return c.name;
  std::string name;
  system_.write_contact_name(c.key, name);
  return name;
}

double MoreauJeanStepper::energy_at_start(const MoreauJeanState& state) const {
  const auto same_bits = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.size() == b.size() &&
           (a.size() == 0 || std::memcmp(a.data(), b.data(),
                                         static_cast<std::size_t>(a.size()) * sizeof(double)) == 0);
  };
  if (produced_.known && same_bits(produced_.q, state.q) && same_bits(produced_.v, state.v))
    return produced_.energy;
  return system_.energy(state.q, state.v);
}

SimulationResult MoreauJeanStepper::simulate(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                                             const InputFunction& input, double duration,
                                             const Observer& observer) {
  if (!(duration >= 0.0) || !std::isfinite(duration))
    throw std::invalid_argument("Moreau–Jean: duration must be >= 0, got " +
                                output::number_text(duration));
  SimulationResult result;
  MoreauJeanState state{0.0, q0, v0};
  check_state(state);
  reset_warm_start();

  RunSummary& summary = result.summary;
  summary.energy_start = system_.energy(state.q, state.v);
  summary.max_energy_rise = -std::numeric_limits<double>::infinity();
  if (observer) {
    StepReport initial;
    initial.statistics.energy_before = initial.statistics.energy_after = summary.energy_start;
    observer(state, initial);
  }

  const double h = options_.dt;
  const long n = duration > 0.0 ? engines::checked_step_count("Moreau–Jean", duration, h) : 0;
  for (long k = 0; k < n; ++k) {
    const double step_size = (k + 1 == n) ? duration - state.t : h;
    if (step_size <= 0.0) break;
    StepReport report = step(state, input, step_size);
    StepStatistics& stats = report.statistics;
    stats.step_index = k + 1;
    summary.max_penetration = std::max(summary.max_penetration, stats.max_penetration);
    summary.worst_residual = std::max(summary.worst_residual, stats.residual);
    summary.max_active_contacts = std::max(summary.max_active_contacts, stats.active_contacts);
    summary.total_solver_iterations += stats.solver_iterations;
    summary.total_solve_seconds += stats.solve_seconds;
    if (!stats.converged) ++summary.solver_failures;
    summary.late_contacts += stats.late_contacts;
    if (!report.advanced) {
      result.status = stats.converged ? RunStatus::kDiverged : RunStatus::kSolverFailed;
      result.message = report.message();
      if (options_.record_steps) result.steps.push_back(stats);
      break;
    }
    summary.steps = k + 1;
    summary.max_energy_rise =
        std::max(summary.max_energy_rise, stats.energy_after - stats.energy_before);
    if (observer) observer(state, report);
    if (options_.record_steps) result.steps.push_back(stats);
    if (options_.record_impulses) result.impulses.push_back(report.impulses());
  }

  // Penetration of the final state as well.
  system_.find_contacts(state.q, state.v, options_.contact_margin, candidates_);
  for (const auto& c : candidates_)
    summary.max_penetration = std::max(summary.max_penetration, -c.gap);
  summary.energy_end = system_.energy(state.q, state.v);
  if (summary.steps == 0) summary.max_energy_rise = 0.0;
  result.final_state = std::move(state);
  return result;
}

}  // namespace impactbench::engines::moreau_jean
