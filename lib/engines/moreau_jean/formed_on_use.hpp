#pragma once
// A value of a step's report formed only when a caller asks for it, so that a step pays nothing
// for what no one reads (the stepper sets a function that captures only itself: std::function
// keeps such a small function without a heap allocation).
#include <functional>
#include <optional>
#include <utility>

namespace impactbench::engines::moreau_jean {

template <typename T>
class FormedOnUse {
 public:
  /// Formed by `form` on first use (an empty T when `form` is empty).
  void set_form(std::function<T()> form) {
    form_ = std::move(form);
    value_.reset();
  }
  void set_value(T value) {
    form_ = nullptr;
    value_ = std::move(value);
  }
  const T& get() const {
    if (!value_) value_ = form_ ? form_() : T{};
    return *value_;
  }

 private:
  std::function<T()> form_;
  mutable std::optional<T> value_;
};

}  // namespace impactbench::engines::moreau_jean
