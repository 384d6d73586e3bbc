#include "lib/metrics/penetration.hpp"

#include <algorithm>

namespace impactbench::metrics {

void PenetrationTracker::add(const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  // Margin 0: the contacts that touch or penetrate.
  system_.find_contacts(q, v, 0.0, contacts_);
  for (const auto& c : contacts_) deepest_ = std::max(deepest_, -c.gap);
}

}  // namespace impactbench::metrics
