#pragma once
// The output samples of a run: at t = 0, every output_interval (from the integrator's dense
// output), at event instants, and at the end. They go to the observer when there is one, else
// into the result.
//
// The observer gets them in batches, in time order, its calls timed as recording. Handing each
// sample over on its own switched the run's clock twice per sample: two reads of the process CPU
// clock, each a system call (about 0.7 µs on the project's 2-core VM), so that at 100 samples per
// second of a bouncing ball the clock cost as much as the integration, and half of it was booked
// to the engine. A batch is filled during the integration (copies of q and v into kept storage,
// booked to the engine) and handed over with one switch each way. Samples go into flat tables
// (sample_table.hpp): no allocation per sample.
#include <cstddef>
#include <functional>
#include <limits>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_types.hpp"
#include "lib/engines/event_driven/flow_session.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/run_timer.hpp"

namespace impactbench::engines::event_driven {

class Sampler {
 public:
  using Observer = std::function<void(const SampleView&)>;

  Sampler(const RunContext& run, const Observer& observer, SampleTable& store, RunTimer& timer)
      : run_(run), observer_(observer), store_(store), timer_(timer) {}

  /// Emits the sample at t = 0; the interval samples follow up to t_end.
  void start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double t_end);
  void emit(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
            const Eigen::Ref<const Eigen::VectorXd>& v);
  /// The interval samples up to t_reached, from the dense output of the integrator's last step.
  void emit_until(double t_reached, const FlowSession& session);
  /// The sample at t_end, unless it was emitted already, and every sample not yet handed over.
  void finish(const Eigen::VectorXd& q, const Eigen::VectorXd& v);
  /// Hands the samples filled so far to the observer (a run that stops early calls it).
  void flush();
  double t_end() const { return t_end_; }
  /// Counts one integrator step; false once more than options.max_steps_between_samples have been
  /// taken since the last sample.
  bool count_step() { return ++steps_since_sample_ <= run_.options.max_steps_between_samples; }

 private:
  /// Appends the sample at (t, q, v), its positions normalised, to `table`.
  void append_sample(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                     const Eigen::Ref<const Eigen::VectorXd>& v, SampleTable& table);

  const RunContext& run_;
  const Observer& observer_;
  SampleTable& store_;
  RunTimer& timer_;  // the observer's samples are recording, the rest integration
  // The observer's next batch, kept between batches (no allocation per sample once grown);
  // batch_size_ samples of at most about 64 k values.
  SampleTable pending_;
  // A sample's state as the system's energy takes it (whole vectors), kept between samples.
  Eigen::VectorXd sample_q_, sample_v_;
  std::size_t batch_size_ = 1;
  double t_end_ = 0.0;
  double next_sample_ = 0.0;
  long sample_index_ = 0;
  double last_sample_time_ = -std::numeric_limits<double>::infinity();
  long steps_since_sample_ = 0;  // the integrator's work since the last sample
};

}  // namespace impactbench::engines::event_driven
