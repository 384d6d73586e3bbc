#include "lib/engines/event_driven/sampler.hpp"

#include <algorithm>

namespace impactbench::engines::event_driven {

void Sampler::start(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, double t_end) {
  t_end_ = t_end;
  // Room for the interval samples and both ends (events add theirs): the result's samples are
  // then not moved as they grow. Capped, so that a tiny interval does not reserve gigabytes.
  const double interval = run_.options.output_interval;
  store_.set_sizes(run_.nq, run_.nv);
  if (!observer_ && interval > 0.0 && t_end > 0.0)
    store_.reserve(static_cast<std::size_t>(std::min(t_end / interval, 1e5)) + 2);
  constexpr std::size_t kMaxBatch = 256, kMaxBatchValues = 1 << 16;
  const auto values_per_sample = static_cast<std::size_t>(run_.nq + run_.nv) + 2;
  batch_size_ = std::clamp<std::size_t>(kMaxBatchValues / values_per_sample, 1, kMaxBatch);
  if (observer_) {
    pending_.set_sizes(run_.nq, run_.nv);
    pending_.reserve(batch_size_);
  }
  emit(0.0, q0, v0);
  sample_index_ = 1;
  next_sample_ = run_.options.output_interval;
}

void Sampler::emit(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                   const Eigen::Ref<const Eigen::VectorXd>& v) {
  last_sample_time_ = t;
  steps_since_sample_ = 0;
  if (!observer_) {
    // Kept in the result, as part of the integration: timing it apart would cost two reads of
    // the process CPU clock (system calls), more than the sample itself.
    append_sample(t, q, v, store_);
    return;
  }
  append_sample(t, q, v, pending_);
  if (pending_.size() >= batch_size_) flush();
}

void Sampler::flush() {
  if (pending_.empty()) return;
  const auto recording = timer_.scoped(RunTimer::Phase::kRecord);
  // Emptied after the batch whatever happens: an observer that throws does not get the batch
  // again.
  struct EmptiedAfter {
    SampleTable& table;
    ~EmptiedAfter() { table.clear(); }
  } const emptied{pending_};
  for (const SampleView& sample : pending_) observer_(sample);
}

void Sampler::append_sample(double t, const Eigen::Ref<const Eigen::VectorXd>& q,
                            const Eigen::Ref<const Eigen::VectorXd>& v, SampleTable& table) {
  if (run_.nq == run_.nv)
    sample_q_ = q;
  else
    sample_q_ = run_.normalized_positions(q);
  sample_v_ = v;
  table.push_back(t, sample_q_, sample_v_, run_.system.energy(sample_q_, sample_v_));
}

void Sampler::emit_until(double t_reached, const FlowSession& session) {
  const double interval = run_.options.output_interval;
  if (interval <= 0.0) return;
  // Only sample times reached: a sample time just past an event instant belongs to the next
  // segment, after the event (its label is the time of its state).
  while (next_sample_ <= t_reached && next_sample_ < t_end_) {
    const auto y = session.interpolate(next_sample_);
    emit(next_sample_, y.head(run_.nq), y.tail(run_.nv));
    ++sample_index_;
    next_sample_ = static_cast<double>(sample_index_) * interval;
  }
}

void Sampler::finish(const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  if (last_sample_time_ < t_end_) emit(t_end_, q, v);
  flush();
}

}  // namespace impactbench::engines::event_driven
