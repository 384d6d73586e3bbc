#include "tools/engines/fixed_step/fixed_step_driver.hpp"

#include <utility>

#include "lib/engines/run_timer.hpp"
#include "lib/engines/step_count.hpp"

namespace impactbench::adapters {

void run_fixed_steps(FixedStepWorld& world, const FixedStepRun& run, engines::RunResult& result) {
  using Phase = engines::RunTimer::Phase;
  engines::ContactEvents events(run.impact);
  const long steps = engines::fixed_step_count(run.engine, run.duration, run.dt);
  engines::RunTimer timer;
  timer.start(Phase::kRecord);
  world.record_state(0.0, result);
  if (result.recording.timing_only) {
    timer.switch_to(Phase::kEngine);
    for (long k = 0; k < steps; ++k) world.step(k * run.dt);
    timer.switch_to(Phase::kRecord);
    world.record_state(steps * run.dt, result);
    result.finish_recording();
    result.step_count = steps;
    result.unconverged_note = "not read in a timing-only run";
    timer.stop();
    result.set_timing(timer);
    return;
  }
  for (long k = 0; k < steps; ++k) {
    const double t = k * run.dt;
    world.before_step(t);
    timer.switch_to(Phase::kEngine);
    world.step(t);
    timer.switch_to(Phase::kRecord);
    const double t_end = (k + 1) * run.dt;
    engines::StepRecord step;
    step.t = t_end;
    const std::vector<engines::ClosedContact> closed = world.read_step(t, step, result);
    events.after_step(t_end, closed, result.events);
    result.add_step(std::move(step));
    world.record_state(t_end, result);
  }
  result.finish_recording();
  result.count_steps(run.has_tolerance);
  timer.stop();
  result.set_timing(timer);
}

}  // namespace impactbench::adapters
