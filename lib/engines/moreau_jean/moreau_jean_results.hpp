#pragma once
// What the Moreau–Jean stepper reports: per contact the impulse and the local velocities the
// contact-law metrics need (Signorini, friction cone, maximal dissipation), per step the solver
// statistics, per run a summary and a status returned as a value.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/moreau_jean/formed_on_use.hpp"
#include "lib/model/contact.hpp"
#include "solvers/common/solver_types.hpp"

namespace impactbench::engines::moreau_jean {

/// The state the stepper advances.
struct MoreauJeanState {
  double t = 0.0;     ///< [s]
  Eigen::VectorXd q;  ///< positions, nq
  Eigen::VectorXd v;  ///< velocities, nv
};

/// One active contact of one step. Impulses are percussions over the step [N·s]; local
/// velocities are [ζ_n, ζ_t...] [m/s] in the contact frame (normal first).
struct ContactImpulse {
  model::ContactKey key;
  std::string name;
  double gap = 0.0;                                   ///< h_n(q_k) at the start of the step [m]
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< world contact point at q_k [m]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< world normal at q_k, towards body_a
  double friction = 0.0;                              ///< μ
  double restitution = 0.0;                           ///< e
  double r_n = 0.0;                                   ///< normal impulse ≥ 0
  // At most three components: fixed capacity, so a step's records allocate no vectors.
  using Local = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1>;
  Local r_t;       ///< tangential impulse, size d
  Local u_before;  ///< [ζ_n, ζ_t] at v_k
  Local u_after;   ///< [ζ_n, ζ_t] at v_{k+1}
};

/// Statistics of one step (step_index 0 is the initial state, before any step).
struct StepStatistics {
  long step_index = 0;
  double t = 0.0;              ///< time at the end of the step [s]
  int candidate_contacts = 0;  ///< contacts found within the margin
  int active_contacts = 0;     ///< contacts in the one-step problem
  int solver_iterations = 0;
  double residual = 0.0;       ///< solver residual (0 without active contacts)
  double solve_seconds = 0.0;  ///< wall time of the contact solve
  bool converged = true;
  /// Solved on the faceted cone (an LCP solver on a spatial problem): `converged` then means the
  /// LCP was solved, while `residual` is still measured on the friction disk.
  bool faceted_cone = false;
  solvers::SolverStatus solver_status = solvers::SolverStatus::kConverged;
  double max_penetration = 0.0;  ///< max(0, −gap) over candidates at the start [m]
  /// Candidates found already penetrated by more than activation_tolerance that were not
  /// candidates of the previous step: an impact the search did not see coming (a warning).
  int late_contacts = 0;
  double energy_before = 0.0;  ///< E(q_k, v_k) [J]
  double energy_after = 0.0;   ///< E(q_{k+1}, v_{k+1}) [J]
};

/// Everything one step produced. The message and the impulses are formed on first use, so that
/// a caller who times the stepping apart from its recording (run_moreau_jean) does not time this
/// bookkeeping as stepping; both are valid until the stepper's next step.
struct StepReport {
  StepStatistics statistics;
  bool advanced = true;  ///< false: the state was left at t_k (failed solve or non-finite state)

  /// Why not advanced, or the solver's note on a warned failure (empty otherwise).
  const std::string& message() const { return message_text.get(); }
  /// The impulses of the step's active contacts.
  const std::vector<ContactImpulse>& impulses() const { return impulse_records.get(); }

  FormedOnUse<std::string> message_text;                     ///< set by the stepper
  FormedOnUse<std::vector<ContactImpulse>> impulse_records;  ///< set by the stepper
};

enum class RunStatus {
  kCompleted,     ///< Reached the requested duration.
  kSolverFailed,  ///< A contact solve failed and on_failure = kStop.
  kDiverged,      ///< The state became non-finite.
};

std::string to_string(RunStatus status);

struct RunSummary {
  long steps = 0;
  double max_penetration = 0.0;  ///< over all steps and the final state [m]
  double energy_start = 0.0;     ///< [J]
  double energy_end = 0.0;       ///< [J]
  double max_energy_rise = 0.0;  ///< max over steps of E_{k+1} − E_k (≤ 0 means none) [J]
  int solver_failures = 0;       ///< non-converged solves (warnings when on_failure = kWarn)
  int late_contacts = 0;         ///< sum of StepStatistics::late_contacts (warnings)
  double worst_residual = 0.0;
  int max_active_contacts = 0;
  long total_solver_iterations = 0;
  double total_solve_seconds = 0.0;
};

struct SimulationResult {
  RunStatus status = RunStatus::kCompleted;
  std::string message;  ///< one line: why the run stopped early (empty when completed)
  MoreauJeanState final_state;
  RunSummary summary;
  std::vector<StepStatistics> steps;                  ///< one per step taken, when record_steps
  std::vector<std::vector<ContactImpulse>> impulses;  ///< per step, when record_impulses
  bool succeeded() const { return status == RunStatus::kCompleted; }
};

}  // namespace impactbench::engines::moreau_jean
