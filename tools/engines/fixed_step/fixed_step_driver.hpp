#pragma once
// The one loop of every fixed-step reference engine (Box2D, Bullet, ODE, MuJoCo, Siconos'
// Moreau–Jean path): step counting, the split of CPU time between the engine's stepping and our
// recording (RunTimer), the contact events, the step records and the samples. An adapter
// supplies its world behind FixedStepWorld: it builds the world, applies the inputs and steps
// it, and reads its states and contacts; the order of those calls is fixed here.
#include <string>
#include <vector>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/impact_criteria.hpp"
#include "lib/engines/run_result.hpp"

namespace impactbench::adapters {

/// An engine's world as the fixed-step loop drives it. Each step from t to t + dt calls
/// before_step(t) and read_step(t, ...) on recording's time and step(t) on the engine's.
class FixedStepWorld {
 public:
  virtual ~FixedStepWorld() = default;
  /// Reads the bodies' state and offers it to `result` as the sample of time t (the initial
  /// state at t = 0, then the end of every step).
  virtual void record_state(double t, engines::RunResult& result) = 0;
  /// Keeps what the step's contacts need of the state at its start (approach speeds).
  virtual void before_step(double t) { (void)t; }
  /// Applies the inputs of time t (forces, hinge torques) and takes one step.
  virtual void step(double t) = 0;
  /// The step's statistics and contacts into `step` (its time is set), raising
  /// result.max_penetration to the deepest contact; returns the contacts closed after it.
  virtual std::vector<engines::ClosedContact> read_step(double t, engines::StepRecord& step,
                                                        engines::RunResult& result) = 0;
};

/// What the loop needs to know of a run besides the world.
struct FixedStepRun {
  std::string engine;  ///< for messages (the step count)
  double dt = 0.0;     ///< [s]
  double duration = 0.0;
  engines::ImpactCriteria impact;
  /// Whether the engine solves its contact problems to a tolerance (RunResult::count_steps).
  bool has_tolerance = false;
};

/// Runs round(duration / dt) steps of `world`, recording into `result`, whose engine name,
/// recording options, column names and settings the adapter has set. Throws
/// std::invalid_argument for a step count that cannot be run (engines::fixed_step_count) and
/// whatever the world throws.
void run_fixed_steps(FixedStepWorld& world, const FixedStepRun& run, engines::RunResult& result);

}  // namespace impactbench::adapters
