#pragma once
// The output samples of a run: at t = 0, every output_interval (from the integrator's dense
// output), at event instants, and at the end. They go to the observer when there is one (timed as
// recording), else into the result.
#include <functional>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_types.hpp"
#include "lib/engines/event_driven/flow_session.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/run_timer.hpp"

namespace impactbench::engines::event_driven {

class Sampler {
 public:
  using Observer = std::function<void(const Sample&)>;

  Sampler(const RunContext& run, const Observer& observer, std::vector<Sample>& store,
          RunTimer& timer)
      : run_(run), observer_(observer), store_(store), timer_(timer) {}

  /// Emits the sample at t = 0; the interval samples follow up to t_end.
  void start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double t_end);
  void emit(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
            const Eigen::Ref<const Eigen::VectorXd>& v);
  /// The interval samples up to t_reached, from the dense output of the integrator's last step.
  void emit_until(double t_reached, const FlowSession& session);
  /// The sample at t_end, unless it was emitted already.
  void finish(const Eigen::VectorXd& q, const Eigen::VectorXd& v);
  double t_end() const { return t_end_; }
  /// Counts one integrator step; false once more than options.max_steps_between_samples have been
  /// taken since the last sample.
  bool count_step() { return ++steps_since_sample_ <= run_.options.max_steps_between_samples; }

 private:
  /// Writes the sample at (t, q, v) into `s`, in its storage.
  void fill_sample(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                   const Eigen::Ref<const Eigen::VectorXd>& v, Sample& s) const;

  const RunContext& run_;
  const Observer& observer_;
  std::vector<Sample>& store_;
  RunTimer& timer_;  // the observer's samples are recording, the rest integration
  Sample observed_;  // the sample handed to the observer, its vectors kept between samples
  double t_end_ = 0.0;
  double next_sample_ = 0.0;
  long sample_index_ = 0;
  double last_sample_time_ = -std::numeric_limits<double>::infinity();
  long steps_since_sample_ = 0;  // the integrator's work since the last sample
};

}  // namespace impactbench::engines::event_driven
