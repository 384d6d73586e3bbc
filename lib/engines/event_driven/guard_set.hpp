#pragma once
// The guards of one segment, CVODE's root functions. Each contact within the tracking margin at
// the segment's start has a slot with two root functions (see event_driven_integrator.hpp):
//   open:  the gap, and 1;
//   slip:  λ_n, and ζ_t·s_ref (slip→stick);
//   stick: λ_n, and μ²λ_n² − ‖λ_t‖² (stick→slip);
// and one more, the approach guard, restarts the segment before an untracked contact can touch.
// A guard that starts a segment at zero is armed only once it has moved clear of zero, so that
// roots of its round-off are ignored.
#include <map>
#include <set>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/run_context.hpp"
#include "lib/engines/event_driven/segment_flow.hpp"

namespace impactbench::engines::event_driven {

/// Why a guard fired (root or watchdog).
enum class Guard { kGap, kLiftoff, kSlipToStick, kStickToSlip };
using FiredGuards = std::map<model::ContactKey, Guard>;

class GuardSet {
 public:
  GuardSet(const RunContext& run, const ContactModes& modes, SegmentFlow& flow)
      : run_(run), modes_(modes), flow_(flow) {}

  /// A new segment tracking `contacts`: one slot each, nothing armed.
  void begin_segment(const std::vector<model::Contact<double>>& contacts);
  int num_slots() const { return static_cast<int>(slots_.size()); }
  int num_roots() const { return 2 * num_slots() + 1; }
  /// CVODE's root functions at (t, y).
  void evaluate(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> g) {
    g = values_at(t, y);
  }
  /// Arms the guards that moved clear of zero, and returns the guards already on the wrong side
  /// (a root CVODE cannot see because the guard started at zero); empty when all is well.
  FiredGuards check(double t, const Eigen::VectorXd& y);
  /// Armed guards within their threshold of zero at an event cross at the same instant (to the
  /// tolerance): e.g. the second corner of a block reaching the friction limit.
  void add_guards_at_zero(double t, const Eigen::VectorXd& y, FiredGuards& fired);
  /// The armed guards among CVODE's roots.
  FiredGuards fired_by(const std::vector<int>& roots) const;
  /// The approach guard is among the roots: an untracked pair came within half the margin.
  bool approach_fired(const std::vector<int>& roots) const {
    return roots.back() != 0 && armed_.back();
  }
  /// Every root function has moved clear of zero since the segment began.
  bool all_armed() const;
  /// True when every contact at the state of the last check (found there for the guards) has
  /// a slot.
  bool tracks_all_checked() const;

 private:
  Eigen::Index approach_index() const { return 2 * static_cast<Eigen::Index>(slots_.size()); }
  const Eigen::VectorXd& values_at(double t, const Eigen::Ref<const Eigen::VectorXd>& y);
  void guard_values(const FlowAt& at, const Eigen::VectorXd& v,
                    Eigen::Ref<Eigen::VectorXd> g) const;
  double approach_guard(const std::vector<model::ContactGap>& gaps,
                        std::size_t tracked_found) const;
  double threshold(Eigen::Index index, ContactMode mode, double force_scale) const;
  /// An open contact (its gap guard, `index`) already moving apart at y.
  bool separating(Eigen::Index index, ContactMode mode, const model::ContactKey& key,
                  const Eigen::VectorXd& y);

  const RunContext& run_;
  const ContactModes& modes_;
  SegmentFlow& flow_;
  std::vector<model::ContactKey> slots_;   // contacts with root functions in this segment
  std::set<model::ContactKey> slot_keys_;  // the same, for the approach guard's lookups
  std::vector<bool> armed_;                // per root function: has moved clear of zero
  // The last evaluation (CVODE evaluates the guards at the end of every step and at every root
  // it returns, where check and add_guards_at_zero look at them again), valid while the flow's
  // scratch still holds what it was computed from.
  struct Cache {
    bool valid = false;
    unsigned long version = 0;
    double t = 0.0;
    Eigen::VectorXd y, g;
  } cache_;
  mutable std::vector<int> closed_index_;  // guard_values' map contact → closed force
};

}  // namespace impactbench::engines::event_driven
