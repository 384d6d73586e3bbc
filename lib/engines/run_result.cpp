#include "lib/engines/run_result.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/output/message_text.hpp"

namespace impactbench::engines {

namespace {

/// "ball.y = nan" for the first non-finite entry of `values`, "" when all are finite.
std::string first_non_finite(const Eigen::VectorXd& values, const std::vector<std::string>& names,
                             const char* fallback) {
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (!std::isfinite(values(i))) {
      const auto index = static_cast<std::size_t>(i);
      const std::string name =
          index < names.size() ? names[index] : fallback + std::to_string(i) + "]";
      return name + " = " + output::number_text(values(i));
    }
  return "";
}

/// The engine's name as messages start with it.
std::string label(const std::string& engine) {
  return engine.empty() ? "run" : engine;
}

}  // namespace

void RunResult::add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double energy) {
  std::string bad = first_non_finite(q, trajectory.position_names, "q[");
  if (bad.empty()) bad = first_non_finite(v, trajectory.velocity_names, "v[");
  if (bad.empty() && std::isinf(energy)) bad = "energy = " + output::number_text(energy);
  if (!bad.empty())
    throw std::runtime_error(label(engine) + ": the state became non-finite at t = " +
                             output::number_text(t) + " (" + bad +
                             "); the values are outside what the engine can "
                             "compute with");
  if (recording.progress) recording.progress(t);
  if (effective_interval_ < 0.0) {
    // Resolved once the engine has named its columns: t, q, v, energy.
    effective_interval_ = recording.sample_interval;
    const double columns = static_cast<double>(trajectory.position_names.size() +
                                               trajectory.velocity_names.size() + 2);
    if (recording.max_values > 0.0 && recording.duration > 0.0) {
      const double rows = std::max(1.0, std::floor(recording.max_values / columns));
      effective_interval_ = std::max(effective_interval_, recording.duration / rows);
    }
  }
  output::TrajectorySample sample{t, std::move(q), std::move(v), energy};
  // The first state is always kept; then one per interval, on the grid k · interval (the
  // slack keeps a step ending at k · dt from missing the grid point it lands on by rounding),
  // and a state at the instant of the last one kept (the event engine's states before and
  // after an event).
  if (sample_count > 0 && effective_interval_ > 0.0 && t != last_kept_time_ &&
      t < next_sample_time_ - 1e-9 * effective_interval_) {
    pending_ = std::move(sample);
    return;
  }
  pending_.reset();
  if (effective_interval_ > 0.0)
    next_sample_time_ = (std::floor(t / effective_interval_ + 1e-9) + 1.0) * effective_interval_;
  keep(std::move(sample));
}

void RunResult::keep(output::TrajectorySample sample) {
  if (sample_count == 0) first_energy = sample.energy;
  last_kept_time_ = sample.t;
  last_energy = sample.energy;
  ++sample_count;
  if (recording.sample_sink) recording.sample_sink(trajectory, sample);
  if (!recording.keep_samples) return;
  if (static_cast<long>(trajectory.samples.size()) >= kMaxKeptRecords)
    throw std::runtime_error(
        label(engine) + ": more than " + std::to_string(kMaxKeptRecords) +
        " samples to keep in memory; sample less often (impactbench run --sample-dt) or use a "
        "shorter duration");
  trajectory.samples.push_back(std::move(sample));
}

void RunResult::finish_recording() {
  if (pending_) keep(std::move(*pending_));
  pending_.reset();
}

void RunResult::add_step(StepRecord step) {
  ++steps_added_;
  contacts_added_ += step.active_contacts;
  if (!step.converged) {
    ++unconverged_added_;
    worst_unconverged_residual = std::max(worst_unconverged_residual, step.residual);
  }
  if (!recording.keep_steps) return;
  if (static_cast<long>(steps.size()) >= kMaxKeptRecords)
    throw std::runtime_error(label(engine) + ": more than " + std::to_string(kMaxKeptRecords) +
                             " step records to keep in memory; use a larger step or a shorter "
                             "duration");
  steps.push_back(std::move(step));
}

void RunResult::count_steps(bool has_tolerance) {
  step_count = steps_added_;
  if (has_tolerance) unconverged_steps = unconverged_added_;
  mean_contacts = steps_added_ == 0
                      ? 0.0
                      : static_cast<double>(contacts_added_) / static_cast<double>(steps_added_);
}

}  // namespace impactbench::engines
