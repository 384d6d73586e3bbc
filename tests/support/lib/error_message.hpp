#pragma once
// The message of the exception a call throws, for tests that check an error names its cause.
#include <string>

namespace impactbench::test_support {

/// what() of the `Exception` that `f()` throws; empty when it throws nothing.
template <typename Exception, typename F>
std::string error_message_of(F&& f) {
  try {
    f();
  } catch (const Exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace impactbench::test_support
