#include "lib/engines/event_driven/flow_callbacks.hpp"

#include <exception>

#include "lib/engines/event_driven/sundials_handles.hpp"

namespace impactbench::engines::event_driven {

bool FlowCallbacks::evaluate_roots(double t, N_Vector state, Eigen::Ref<Eigen::VectorXd> out) {
  ++root_evaluations;
  try {
    roots(t, view(state), out);
    return true;
  } catch (const std::exception& error) {
    root_error = error.what();
  } catch (...) {
    root_error = "unknown error";
  }
  return false;
}

int FlowCallbacks::evaluate_rhs(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                                Eigen::Ref<Eigen::VectorXd> out) {
  try {
    rhs(t, y, out);
    return out.allFinite() ? 0 : 1;
  } catch (const std::exception& error) {
    rhs_error = error.what();
  } catch (...) {
    rhs_error = "unknown error";
  }
  return -1;
}

int FlowCallbacks::rhs_callback(double t, N_Vector y, N_Vector ydot, void* user) {
  return static_cast<FlowCallbacks*>(user)->evaluate_rhs(t, view(y), view(ydot));
}

int FlowCallbacks::root_callback(double t, N_Vector y, double* g, void* user) {
  auto* self = static_cast<FlowCallbacks*>(user);
  Eigen::Map<Eigen::VectorXd> out(g, self->num_roots);
  return self->evaluate_roots(t, y, out) ? 0 : -1;
}

void FlowCallbacks::error_callback(int, const char* module, const char* function, char* message,
                                   void* user) {
  auto* self = static_cast<FlowCallbacks*>(user);
  self->last_error = std::string(module) + "/" + function + ": " + message;
}

}  // namespace impactbench::engines::event_driven
