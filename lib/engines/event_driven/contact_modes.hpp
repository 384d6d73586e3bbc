#pragma once
// The hybrid state of a run's contacts: the mode of each contact met so far, its slip direction
// reference and its count of consecutive impacts (for the Zeno rule). A contact never seen is
// open.
#include <map>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/constrained_flow.hpp"
#include "lib/engines/event_driven/event_types.hpp"

namespace impactbench::engines::event_driven {

struct TrackedContact {
  ContactMode mode = ContactMode::kOpen;
  Eigen::VectorXd slip_reference;
  int impacts_in_row = 0;  ///< consecutive impacts, reset by a lift-off (Zeno detection)
};

class ContactModes {
 public:
  /// The entry of `key`, created open when new.
  TrackedContact& at(const model::ContactKey& key) { return tracked_[key]; }
  ContactMode mode_of(const model::ContactKey& key) const;
  int impacts_in_row(const model::ContactKey& key) const;
  /// Slip only: the slip direction reference of a tracked contact.
  const Eigen::VectorXd& slip_reference(const model::ContactKey& key) const {
    return tracked_.at(key).slip_reference;
  }
  /// True when every contact is open (free flight).
  bool all_open() const;
  /// The closed contacts among `contacts` (pointers into it), for the constrained flow.
  std::vector<ClosedContact> closed_among(
      const std::vector<model::Contact<double>>& contacts) const;
  /// The same into `closed`, keeping its storage (the flow asks at every right-hand side).
  void closed_among(const std::vector<model::Contact<double>>& contacts,
                    std::vector<ClosedContact>& closed) const;
  /// The closed contacts' modes (an event state's record).
  std::map<model::ContactKey, ContactMode> closed_modes() const;

 private:
  std::map<model::ContactKey, TrackedContact> tracked_;
};

}  // namespace impactbench::engines::event_driven
