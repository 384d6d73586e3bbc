#pragma once
// The vector a solve starts from, or none. Made from a pointer to a VectorXd or to a
// CapacityVector (a kept answer, SolverResult::solution), or from nullptr for none, so that a
// caller passes `&vector` of either kind; read through a view, without a copy.
#include <cstddef>
#include <optional>

#include "solvers/common/capacity_vector.hpp"

namespace impactbench::solvers {

class WarmStart {
 public:
  WarmStart() = default;
  WarmStart(std::nullptr_t) {}                // NOLINT(google-explicit-constructor)
  WarmStart(const Eigen::VectorXd* vector) {  // NOLINT(google-explicit-constructor)
    if (vector != nullptr) view_.emplace(*vector);
  }
  WarmStart(const CapacityVector* vector) {  // NOLINT(google-explicit-constructor)
    if (vector != nullptr) view_.emplace(*vector);
  }

  bool given() const { return view_.has_value(); }
  /// The values; only when given().
  const VectorView& operator*() const { return *view_; }
  const VectorView* operator->() const { return &*view_; }
  /// `warm_start == nullptr`: none given, as for the pointer it stands for.
  friend bool operator==(const WarmStart& warm_start, std::nullptr_t) {
    return !warm_start.given();
  }

 private:
  std::optional<VectorView> view_;
};

}  // namespace impactbench::solvers
