#pragma once
// Scratch storage kept per thread between calls, so that a solver called at every step (the time
// stepper's) reuses its buffers instead of allocating them, and lent to one call at a time: a
// call made while another one holds it on the same thread (a solve started from a caller's
// monitor) gets scratch of its own, so that neither overwrites the other's.
#include <memory>

namespace impactbench::solvers {

/// Holds the thread's T for its lifetime, or a fresh T when the thread's is in use or the caller
/// asks for its own (`keep` false: a problem too large to keep its storage for). Each call site
/// names its own T (a struct of its buffers), so that sites do not share one T.
template <typename T>
class ThreadKeptLease {
 public:
  explicit ThreadKeptLease(bool keep = true) {
    Kept& kept = this_thread();
    if (keep && !kept.in_use) {
      kept.in_use = true;
      kept_ = &kept;
      value_ = &kept.value;
    } else {
      own_ = std::make_unique<T>();
      value_ = own_.get();
    }
  }
  ~ThreadKeptLease() {
    if (kept_ != nullptr) kept_->in_use = false;
  }
  ThreadKeptLease(const ThreadKeptLease&) = delete;
  ThreadKeptLease& operator=(const ThreadKeptLease&) = delete;

  T& operator*() const { return *value_; }
  T* operator->() const { return value_; }

 private:
  struct Kept {
    T value;
    bool in_use = false;
  };
  static Kept& this_thread() {
    thread_local Kept kept;
    return kept;
  }

  Kept* kept_ = nullptr;    // not owned: the thread's, when this lease holds it
  std::unique_ptr<T> own_;  // a nested call's own
  T* value_ = nullptr;      // kept_->value or *own_
};

}  // namespace impactbench::solvers
