#pragma once
// A non-owning reference to a callable, for parameters that are called during the call and not
// kept: unlike std::function it never allocates (a lambda capturing more than two pointers does
// not fit std::function's small buffer), so a solve called at every step can take its sweep and
// residual as lambdas without a heap allocation. The callable must outlive the reference.
#include <memory>
#include <type_traits>
#include <utility>

namespace impactbench::solvers {

template <typename Signature>
class FunctionRef;

template <typename Result, typename... Args>
class FunctionRef<Result(Args...)> {
 public:
  FunctionRef() = default;
  template <typename Callable,
            typename = std::enable_if_t<!std::is_same_v<std::decay_t<Callable>, FunctionRef> &&
                                        std::is_invocable_r_v<Result, Callable&, Args...>>>
  FunctionRef(Callable&& callable) noexcept  // NOLINT(google-explicit-constructor): as a lambda
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(callable)))),
        call_([](void* object, Args... args) -> Result {
          return (*static_cast<std::remove_reference_t<Callable>*>(object))(
              std::forward<Args>(args)...);
        }) {}

  Result operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }
  /// False for a default-constructed (empty) reference.
  explicit operator bool() const { return call_ != nullptr; }

 private:
  void* object_ = nullptr;
  Result (*call_)(void*, Args...) = nullptr;
};

}  // namespace impactbench::solvers
