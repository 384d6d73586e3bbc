#pragma once
// The Moreau–Jean time-stepper (event-capturing): one nonsmooth problem per step, no event
// location. One step from (t_k, q_k, v_k) with step h and θ ∈ [0.5, 1]:
//
//   1. Candidates: system.find_contacts(q_k, v_k, contact_margin), plus every contact within
//      the margin at the predicted end of the step q̃ = q_k advanced by h with
//      (1 − θ) v_k + θ v_free (the search follows the motion: a pair that free flight closes
//      within the step is a candidate whatever h is). A candidate found penetrated by more than
//      activation_tolerance that was not a candidate the step before is counted as a late
//      contact (StepStatistics::late_contacts): something the prediction could not see (a
//      body pushed by an impulse of this step) let it close unseen.
//      Active: the candidates whose predicted gap g_k + γ h ζ_n,k ≤ activation_tolerance
//      (γ = activation_horizon, default θ: the gap at the θ-point where the θ-method evaluates
//      the step; Siconos 4.4 uses γ = 1/2, which is θ at the default θ = 1/2).
//   2. Smooth part, θ-method (free_motion.hpp), computed first (the search of step 1 uses it):
//      by default with the forces at the θ-point (q_θ = q_k advanced by θh with v_k,
//      f = S u(t_k + θh) − H(q_θ, v_k)) and the system's dampers C = ∂H/∂v taken at v_θ,
//        v_free = v_k + h (M(q_θ) + hθ C)⁻¹ f,
//      or (ForceTreatment::kLinearlyImplicit) the standard linearly-implicit variant
//        v_free = v_k + Â⁻¹ (h f_k − h²θ K v_k),  Â = M + hθ C + h²θ² K,
//      M⁻¹ (Â⁻¹) is formed per diagonal block (block_diagonal_inverse.hpp); below Â = M when
//      the forces are explicit.
//   3. Contact law at velocity level (Moreau's impact law with Newton restitution): per active
//      contact, with u_n = ζ_n^{k+1} + e min(ζ_n^k, 0) and u_t = ζ_t^{k+1},
//        0 ≤ r_n ⊥ u_n ≥ 0 and Coulomb's law on (r_t, u_t) with cone μ r_n,
//      written as u = W r + q with W = J Â⁻¹ Jᵀ (delassus_assembly.hpp) and solved by
//      solve_friction(name), warm-started with the previous step's impulses of contacts with the
//      same ContactKey. The LCP solvers reach it through the friction driver's conversions (planar:
//      exact; spatial: faceted cone with cone_facets facets; such a solve counts as converged
//      when its LCP converged, flagged StepStatistics::faceted_cone, its residual measured on the
//      friction disk).
//   4. v_{k+1} = v_free + Â⁻¹ Jᵀ r,
//      q_{k+1} = q_k advanced by h with (1 − θ) v_k + θ v_{k+1} (integrate_position).
//
// With θ = 1/2 and constant forces the free flight is exact at the nodes. Impacts are applied
// at the step before the gap would close, so the time of an impact is off by up to h: errors of
// impact quantities are O(h).
//
// Like Drake's integrators the stepper holds a const reference to the system: the system must
// outlive it. Misuse (bad sizes, NaN state, invalid options, a contact with μ < 0 or e ∉ [0,1])
// throws std::invalid_argument; solver non-convergence is returned as a value.
#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lib/engines/moreau_jean/delassus_assembly.hpp"
#include "lib/engines/moreau_jean/free_motion.hpp"
#include "lib/engines/moreau_jean/moreau_jean_options.hpp"
#include "lib/engines/moreau_jean/moreau_jean_results.hpp"
#include "lib/model/contact_key_index.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "solvers/friction/friction_solvers.hpp"

namespace impactbench::engines::moreau_jean {

/// u(t), size nu (may be empty when the system has no inputs).
using InputFunction = std::function<Eigen::VectorXd(double t)>;
/// Called with the initial state (report with step_index 0 and no impulses) and after every
/// accepted step.
using Observer = std::function<void(const MoreauJeanState&, const StepReport&)>;

class MoreauJeanStepper {
 public:
  MoreauJeanStepper(const model::LagrangianSystem<double>& system, MoreauJeanOptions options);

  const MoreauJeanOptions& options() const { return options_; }
  const model::LagrangianSystem<double>& system() const { return system_; }

  /// Advances `state` by h (options().dt unless given) if the step succeeds. When the contact
  /// solve fails and on_failure = kStop, or the new state is not finite, `state` is left as it
  /// was; check report.statistics.converged and the returned report.
  StepReport step(MoreauJeanState& state, const InputFunction& input);
  StepReport step(MoreauJeanState& state, const InputFunction& input, double h);

  /// Runs from (0, q0, v0) for `duration` [s] in steps of dt (the last one shortened to land on
  /// `duration`). `input` may be empty for systems without inputs.
  SimulationResult simulate(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                            const InputFunction& input, double duration,
                            const Observer& observer = {});

  /// Forgets the impulses kept for warm starts.
  void reset_warm_start() {
    warm_start_impulses_.clear();
    previous_candidates_.clear();
  }

 private:
  void check_state(const MoreauJeanState& state) const;
  Eigen::VectorXd input_at(const InputFunction& input, double t) const;
  /// Fills candidates_ for the step from (q, v) with free velocity v_free (step 1 above).
  void find_candidates(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                       const Eigen::VectorXd& v_free, double h);

  // The stages of one step, in the order step() runs them (moreau_jean_stepper.cpp).
  const FreeMotion& free_motion_stage(const MoreauJeanState& state, const InputFunction& input,
                                      double h);
  std::span<const model::Contact<double>> contact_selection_stage(const Eigen::VectorXd& q,
                                                                  const Eigen::VectorXd& v,
                                                                  const Eigen::VectorXd& v_free,
                                                                  double h, StepStatistics& stats);
  bool contact_solve_stage(std::span<const model::Contact<double>> active,
                           const MoreauJeanState& state, const FreeMotion& free,
                           StepReport& report);
  void advance_stage(MoreauJeanState& state, std::span<const model::Contact<double>> active,
                     double h, StepReport& report);

  /// The energy of `state`: the one the last step found for the state it produced when `state`
  /// is that state to the bit (as it is for a caller stepping in a loop), else evaluated.
  double energy_at_start(const MoreauJeanState& state) const;

  /// A candidate's name: its own, or the system's for its key where the search left it unnamed
  /// (find_reachable_contacts), formed only for what the step reports.
  std::string contact_name(const model::Contact<double>& c) const;

  /// The keys of the first `count` candidates: the active ones after step 1.
  std::span<const model::ContactKey> active_keys(std::size_t count) const {
    return {selected_keys_.data(), count};
  }

  const model::LagrangianSystem<double>& system_;
  MoreauJeanOptions options_;
  solvers::FrictionSolver solver_;  // options_.solver, resolved once
  // Buffers reused across steps, so that a step in steady state allocates no contact storage:
  // the candidates are evaluated in place, the active ones moved to the front by swaps.
  // The previous step's candidates, the active ones first: for late contacts and, the active
  // ones (positions below warm_start_impulses_.size()), for warm starts. One index serves both,
  // as the active keys are the first of the candidates' keys.
  model::ContactKeyIndex previous_candidates_;
  // The previous step's active contacts' impulses (1 + d ≤ 3), by position in that index.
  std::vector<std::array<double, 3>> warm_start_impulses_;
  std::vector<model::Contact<double>> candidates_;  // the active ones first after step 1
  bool candidates_named_ = true;                    // false when the search left their names empty
  std::vector<model::Contact<double>> predicted_;   // contacts at the predicted end of the step
  std::vector<model::ContactKey> candidate_keys_;   // sorted keys (the fallback search only)
  // The keys of candidates_ in their order after step 1 (the active ones first, as found):
  // the warm start and the next step's index read these instead of the contacts. The next
  // step's lookups of its active candidates then mostly meet their key at the hint.
  std::vector<model::ContactKey> selected_keys_;
  Eigen::VectorXd speed_bound_;  // per velocity coordinate, max(|v|, |v_blend|): find_candidates
  Eigen::VectorXd v_blend_;      // (1 − θ) v_k + θ v (v_free in the search, v_{k+1} to advance)
  Eigen::VectorXd q_next_;       // q_{k+1}, swapped into the state
  Eigen::MatrixXd zeta_before_;  // (1 + d) × at least the active ones: ζ at v_k
  solvers::CapacityVector warm_;              // the warm start of the solve (kept capacity)
  solvers::SolverResult result_;              // the solve's answer (its r swapped into r_)
  solvers::CapacityVector impulse_velocity_;  // M⁻¹ Jᵀ r, added to v_free
  // The step's results that its report forms its impulses and message from on use, kept until
  // the next step: v_{k+1}, the impulses r, the active contacts (the front of candidates_) and
  // the failed solve.
  Eigen::VectorXd v_next_;
  solvers::CapacityVector r_;  // kept capacity: its storage alternates with result_.solution's
  std::span<const model::Contact<double>> active_;
  struct FailedSolve {
    double t = 0.0;
    solvers::SolverResult result;  // status, residual, iterations and note only
  } failed_solve_;
  // The state the last step produced (q, v) and its energy, which the next step's energy before
  // it repeats when it starts from there.
  struct ProducedState {
    Eigen::VectorXd q, v;
    double energy = 0.0;
    bool known = false;
  } produced_;
  DelassusSystem delassus_;  // the step's problem, assembled into the previous step's storage
  Eigen::SparseMatrix<double> constant_mass_inverse_;  // M⁻¹ of a system with constant M
  FreeMotion free_motion_;  // the step's smooth part, computed into the previous step's storage
};

}  // namespace impactbench::engines::moreau_jean
