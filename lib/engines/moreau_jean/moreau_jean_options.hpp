#pragma once
// Settings of the Moreau–Jean time-stepper. A plain struct with documented defaults, filled
// directly by the scenario loader and `--set`; `validate` names the first bad field.
#include <optional>
#include <string>

#include "lib/engines/impact_criteria.hpp"

namespace impactbench::engines::moreau_jean {

/// What the stepper does when the one-step contact problem is not solved to tolerance.
enum class OnFailure {
  kStop,  ///< End the run with status kSolverFailed at the failing step (state not advanced).
  kWarn,  ///< Apply the solver's best iterate, count a warning and continue (only after an
          ///< iteration limit or a stall; a problem the solver rejects still stops the run).
};

/// How the smooth forces f = S u − H enter the θ-method (see moreau_jean_stepper.hpp).
enum class ForceTreatment {
  /// f evaluated once at (q_k + θ h v_k, v_k), except the dampers the system differentiates in
  /// closed form (LagrangianSystem::damping_matrix), taken θ-implicitly in v at no extra cost:
  /// the choice for piles (H constant). With springs this is the Störmer–Verlet step: energy
  /// oscillates by O(h²), not monotone; second order with or without dampers.
  kExplicit,
  /// f linearised about (q_k, v_k) and taken θ-implicitly, with K = ∂(H − S u)/∂q and
  /// C = ∂(H − S u)/∂v by central differences (4 nv evaluations of H per step: small systems
  /// only). For linear springs and dampers with θ = 1/2 this is the trapezoidal rule: energy
  /// never rises without input work.
  kLinearlyImplicit,
};

struct MoreauJeanOptions {
  double dt = 1e-3;             ///< Step size h [s], > 0.
  double theta = 0.5;           ///< θ of the θ-method, in [0.5, 1].
  std::string solver = "nsgs";  ///< Friction-contact solver name (see friction_solvers()).
  double tolerance = 1e-10;     ///< Solver residual tolerance (FCLIB measure, relative).
  int max_iterations = 1000;    ///< Solver iteration limit (sweeps, pivots, Newton steps).
  OnFailure on_failure = OnFailure::kStop;
  /// A warm-started solve that ends unconverged is repeated from zero impulses (the iterations
  /// of both count). Measured: nsn stalls from some pile steps' previous impulses and solves
  /// the same problems from zero in 13–25 Newton steps.
  bool cold_restart = true;
  ForceTreatment forces = ForceTreatment::kExplicit;
  double jacobian_step = 1e-6;  ///< Central-difference step for K and C [-], scaled by 1+|x|.
  /// Candidate contacts are those with gap below this distance [m] at the start of a step, plus
  /// those the free motion brings within it by the end of the step (the search follows the
  /// motion, so no step size lets a closing contact go unseen; see moreau_jean_stepper.hpp).
  double contact_margin = 0.01;
  /// A candidate becomes active when its predicted gap g_k + γ h ζ_n,k is at most
  /// `activation_tolerance` [m], γ = `activation_horizon` ∈ [0, 1]. Unset: γ = θ, the gap
  /// predicted at the θ-point t_k + θh where the θ-method evaluates the step (Siconos 4.4: γ =
  /// 1/2, tolerance 0; γ = 1 looks one full step ahead and opens contacts a step early).
  std::optional<double> activation_horizon;
  /// Absorbs round-off in the gaps of bodies placed exactly in contact (stacks) [m], >= 0.
  double activation_tolerance = 1e-9;
  /// Facets of the polyhedral cone when a spatial problem is solved by an LCP solver (≥ 3).
  int cone_facets = 8;
  /// Delassus matrices with at most this many rows are assembled dense, larger ones sparse;
  /// for a solver that sweeps W's factors (nsgs) W is not formed at any size.
  int dense_delassus_max_rows = 240;
  /// Keep every step's contact impulses in the simulation result (memory grows with the run).
  /// Off by default: an observer sees each step's impulses in its StepReport, which is all the
  /// engine adapter needs; only callers that read SimulationResult::impulses turn it on.
  bool record_impulses = false;
  /// Off by default, likewise for SimulationResult::steps: the run's figures are kept as running
  /// aggregates (RunSummary), so a run's memory does not grow with its step count.
  bool record_steps = false;
  /// When a closing contact is reported as an impact event (the engine adapter's event
  /// derivation; the stepper itself does not read it).
  ImpactCriteria impact;
};

/// Throws std::invalid_argument naming the first field out of range. The solver name is checked
/// against the friction-solver registry.
void validate(const MoreauJeanOptions& options);

/// γ of the activation rule: activation_horizon when set, θ otherwise.
double activation_horizon(const MoreauJeanOptions& options);

}  // namespace impactbench::engines::moreau_jean
