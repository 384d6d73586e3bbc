#pragma once
// Settings of the event-driven integrator, with units and defaults. Filled by the CLI
// (`--tol` sets both tolerances) and by the scenario loader.
#include <string>

namespace impactbench::engines::event_driven {

/// The integrator of the flow between events (flow_session.hpp).
enum class FlowMethod {
  kBdf,    ///< CVODE BDF (orders 1–5), robust for stiff springs/dampers.
  kAdams,  ///< CVODE Adams–Moulton (orders 1–12), cheaper on smooth non-stiff flows.
  kErk,    ///< ARKODE ERKStep: an explicit Runge–Kutta pair (erk_pair), one-step, non-stiff.
  /// The same pair stepped by our own driver (own_erk_session.hpp): less work per step, roots
  /// always located on the dense output.
  kOwnErk,
};

/// The embedded explicit Runge–Kutta pair of `method = erk` and `own_erk` (ARKODE's Butcher
/// tables).
enum class ErkPair {
  kDormandPrince54,  ///< Dormand–Prince 5(4), 7 stages.
  kVerner65,         ///< Verner 6(5), 8 stages.
  kFehlberg87,       ///< Fehlberg 8(7), 13 stages.
};

struct EventDrivenOptions {
  double relative_tolerance = 1e-10;  ///< CVODE rtol [-]
  double absolute_tolerance = 1e-10;  ///< CVODE atol, in the units of each state component
  FlowMethod method = FlowMethod::kAdams;
  ErkPair erk_pair = ErkPair::kDormandPrince54;  ///< The pair of `erk` and `own_erk`.
  double max_step = 0.0;                         ///< Largest CVODE step [s]; 0 = unlimited.
  /// First step after every (re)start [s]; 0 = the integrator's estimate. A small first step
  /// keeps CVODE's order-1 start of each segment from dominating the global error, and lets a
  /// guard that starts at zero be armed before it can cross again (method = erk as well).
  double initial_step = 1e-8;
  /// Largest step growth factor during CVODE's first steps after a (re)start [-] (> 1).
  double startup_step_growth = 4.0;
  /// The startup growth limit holds until CVODE's method order reaches this; then the early
  /// steps may grow by up to 10⁴ per step (a flight under constant forces, exact at order 2,
  /// takes a handful of steps instead of a dozen: 361 CVODE steps instead of 718 on event_bench's
  /// bouncing ball). 0 (default) keeps the limit for all early steps: lifted, the early steps
  /// are only as accurate as the tolerance asks, and loose tolerances lose the accuracy the slow
  /// startup gave them (rocking block at rtol 1e-4: error 1.1e-2 instead of 1.2e-3).
  int startup_order = 0;
  /// Locate the guards' roots on the integrator's dense output (root_search.hpp: fewer guard
  /// evaluations, 944 instead of 1,421 on the bouncing ball) instead of by CVODE's (ARKODE's)
  /// rootfinding (default). Roots agree to CVODE's root tolerance, not to the bit, and a run that
  /// depends on the last bits of an event time can change (event_bench's plank box at rtol 1e-8
  /// ends in a stalled Lemke at an impact).
  bool dense_output_root_search = false;
  /// CVODE's corrector convergence coefficient relative to the local error test (its default
  /// is 0.1) [-].
  double nonlinear_convergence_coefficient = 1e-3;

  double output_interval = 0.01;  ///< Sample spacing [s]; 0 = samples only at t0, events, end.
  /// Most CVODE steps from one output sample (interval or event sample) to the next before the
  /// run stops with kIntegratorFailure. A flow too stiff for the method (Adams on a stiff
  /// spring) collapses the step size and would crawl for hours; BDF (`method = bdf`) handles it.
  long max_steps_between_samples = 100000;
  bool sample_events = true;        ///< Add samples just before and after each event instant.
  int max_events = 10000;           ///< Stop with kMaxEvents beyond this many events.
  int max_events_per_instant = 50;  ///< Event processing passes at one time before kStalled.

  /// Contacts are requested from the system with this margin [m]: each segment tracks (with
  /// root functions) the contacts within it at its start, and one more root function restarts
  /// the segment when another contact's gap falls below half the margin, before it can touch.
  /// A margin below the distance to the second neighbours keeps a row of N balls at N − 1
  /// tracked pairs instead of N(N − 1)/2.
  double contact_margin = 1e3;
  /// A gap within this of zero counts as touching at an event [m].
  double gap_tolerance = 1e-9;
  /// |ζ_n| below this counts as resting; ‖ζ_t‖ below this counts as sticking [m/s].
  double velocity_tolerance = 1e-8;
  /// Forces/accelerations below this (relative to the problem's scale) count as zero in the
  /// mode decisions [-].
  double complementarity_tolerance = 1e-9;

  /// Zeno: after this many consecutive impacts of one contact, a post-impact normal velocity
  /// below `zeno_velocity` [m/s] makes the contact persistent (closed, ζ_n = 0).
  int zeno_impact_count = 5;
  double zeno_velocity = 1e-2;
  /// Zeno: a predicted time to the next impact of the contact (2ζ_n⁺/|normal acceleration|)
  /// below this makes the contact persistent at once [s].
  double zeno_min_interval = 1e-4;

  // Thresholds of the contact algebra [-]. The defaults are the values the integrator has
  // always used; as options, a study can see what depends on them.

  /// Rank threshold of the constrained flow's Delassus matrix D (relative to its largest pivot):
  /// directions below it count as redundant constraints whose forces are spread
  /// (constrained_flow.hpp). Also used by the Zeno rule's prediction of the next flight.
  double flow_rank_threshold = 1e-10;
  /// A flow solution λ with ‖Dλ − b‖ above this × (1 + ‖b‖ + ‖D‖‖λ‖) means the modes are
  /// inconsistent (the run stops with kSingularDynamics).
  double flow_residual_tolerance = 1e-8;
  /// Floor of a sticking contact's friction capacity μλ_n, relative to the largest contact
  /// force, when redundant tangential forces are spread in proportion to it.
  double friction_capacity_floor = 1e-9;
  /// The single-contact stick impact map is taken only when its impulse solves the stick
  /// conditions to this × (1 + ‖ζ⁻‖) (a singular Delassus matrix fails it: the slip map is used).
  double stick_impulse_residual = 1e-9;

  /// Solver names (solvers/): planar contact problems are LCPs solved by `lcp_solver`;
  /// spatial ones with friction go to `friction_solver`.
  std::string lcp_solver = "lemke";
  std::string friction_solver = "nsgs";
  /// Residual tolerance of those solvers, relative to 1 + ‖q‖∞ of each problem [-].
  double solver_tolerance = 1e-10;
  int solver_max_iterations = 2000;
};

}  // namespace impactbench::engines::event_driven
