#pragma once
// How every engine times a run: process CPU time (CLOCK_PROCESS_CPUTIME_ID, all threads of this
// process; not the time spent waiting for a core) split between the engine's stepping and our
// recording of its output, and wall-clock time of the whole span. The split is what makes
// engines comparable: Box2D's or Bullet's step must not be charged with the adapter's work of
// reading manifolds and building samples, nor our own stepper with its observer.
#include <time.h>

#include <chrono>

namespace impactbench::engines {

/// Process CPU time since an unspecified origin [s].
inline double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Books process CPU time to two phases. Each switch reads the clock once and charges the time
/// since the previous switch to the phase that was running, so a step costs two clock reads.
class RunTimer {
 public:
  enum class Phase { kEngine, kRecord };

  /// Starts both clocks with `phase` running.
  void start(Phase phase) {
    wall_start_ = std::chrono::steady_clock::now();
    last_ = process_cpu_seconds();
    phase_ = phase;
  }
  void switch_to(Phase phase) {
    const double now = process_cpu_seconds();
    (phase_ == Phase::kEngine ? engine_ : record_) += now - last_;
    last_ = now;
    phase_ = phase;
  }
  /// Runs `phase` until the end of the scope, then the phase that ran before.
  class [[nodiscard]] Scope {
   public:
    Scope(RunTimer& timer, Phase phase) : timer_(timer), previous_(timer.phase_) {
      timer_.switch_to(phase);
    }
    ~Scope() { timer_.switch_to(previous_); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    RunTimer& timer_;
    Phase previous_;
  };
  Scope scoped(Phase phase) { return Scope(*this, phase); }

  /// Ends the running phase and the wall-clock span.
  void stop() {
    switch_to(phase_);
    wall_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  }

  double engine_cpu_seconds() const { return engine_; }
  double record_cpu_seconds() const { return record_; }
  double wall_seconds() const { return wall_; }

 private:
  std::chrono::steady_clock::time_point wall_start_;
  double last_ = 0.0;
  Phase phase_ = Phase::kEngine;
  double engine_ = 0.0, record_ = 0.0, wall_ = 0.0;
};

}  // namespace impactbench::engines
