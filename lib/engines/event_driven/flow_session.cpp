#include "lib/engines/event_driven/flow_session.hpp"

#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "lib/engines/event_driven/cvode_session.hpp"
#include "lib/engines/event_driven/erk_session.hpp"
#include "lib/engines/event_driven/own_erk_session.hpp"
#include "lib/engines/event_driven/root_search.hpp"

namespace impactbench::engines::event_driven {

FlowSession::FlowSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots,
                         std::string library, std::string root_failure_flag)
    : library_(std::move(library)),
      root_failure_flag_(std::move(root_failure_flag)),
      size_(size),
      own_root_search_(options.dense_output_root_search) {
  if (options.relative_tolerance <= 0.0 || options.absolute_tolerance <= 0.0)
    throw std::invalid_argument("event-driven: tolerances must be positive");
  callbacks_.rhs = std::move(rhs);
  callbacks_.roots = std::move(roots);
  SUNContext ctx = nullptr;
  if (SUNContext_Create(nullptr, &ctx) < 0)
    throw std::runtime_error(library_ + " setup failed in SUNContext_Create");
  context_.reset(ctx);
  y_.reset(N_VNew_Serial(size, ctx));
  dense_.reset(N_VNew_Serial(size, ctx));
  probe_.reset(N_VNew_Serial(size, ctx));
  if (!y_ || !dense_ || !probe_) throw std::runtime_error(library_ + ": allocation failed");
  N_VConst(0.0, y_.get());
}

FlowSession::~FlowSession() = default;

void FlowSession::restart(double t0, const Eigen::VectorXd& y0, int num_roots, double t_end) {
  view(y_.get()) = y0;
  callbacks_.num_roots = num_roots;
  callbacks_.root_evaluations = 0;
  have_g_lo_ = false;
  step_pending_ = false;
  found_.assign(static_cast<std::size_t>(num_roots), 0);
  restart_library(t0, own_root_search_ ? 0 : num_roots, t_end);
  t_ = t0;
  restart_time_ = t0;
  after_root_ = false;
}

FlowSession::StepOutcome FlowSession::step() {
  const double t_root = t_;
  illegal_input_ = false;
  StepOutcome outcome =
      callbacks_.num_roots == 0 || !own_root_search_ ? library_step() : step_with_own_root_search();
  if (outcome == StepOutcome::kFailure && after_root_ && illegal_input_) {
    outcome = StepOutcome::kCloseRoots;
    t_ = t_root;
  }
  after_root_ = outcome == StepOutcome::kRoot;
  return outcome;
}

FlowSession::StepOutcome FlowSession::step_with_own_root_search() {
  FlowCallbacks& c = callbacks_;
  const auto guard_failure = [&] {
    failure_ = root_failure_message();
    return StepOutcome::kFailure;
  };
  if (!have_g_lo_) {
    g_lo_.resize(c.num_roots);
    if (!c.evaluate_roots(t_, y_.get(), g_lo_)) return guard_failure();
    t_lo_ = t_;
    have_g_lo_ = true;
  }
  if (!step_pending_) {
    const StepOutcome outcome = library_step();
    if (outcome == StepOutcome::kFailure) return outcome;
    g_end_.resize(c.num_roots);
    if (!c.evaluate_roots(t_, y_.get(), g_end_)) return guard_failure();
    y_end_ = view(y_.get());
    t_end_of_step_ = t_;
    outcome_at_end_ = outcome;
    step_pending_ = true;
  }
  bool crossing = false;
  for (Eigen::Index i = 0; i < c.num_roots; ++i)
    crossing = crossing || crosses_downwards(g_lo_[i], g_end_[i]);
  if (crossing) {
    // The libraries' root tolerance: 100 units of round-off of the step's end time and size.
    const double tolerance =
        100.0 * DBL_EPSILON * (std::abs(t_end_of_step_) + std::abs(last_step_size()));
    bool ok = true;
    const auto guards_at = [&](double t, Eigen::Ref<Eigen::VectorXd> out) {
      if (!ok) {  // after a failure: end the search
        out.setZero();
        return;
      }
      dense_output(t, probe_.get());
      ok = c.evaluate_roots(t, probe_.get(), out);
    };
    RootBracket root =
        locate_earliest_root(guards_at, t_lo_, g_lo_, t_end_of_step_, g_end_, tolerance);
    if (!ok) return guard_failure();
    // The state returned is the dense output at the root, as the libraries' own root return.
    t_ = root.t_hi;
    dense_output(t_, y_.get());
    t_lo_ = t_;
    g_lo_ = std::move(root.g_hi);
    found_ = std::move(root.found);
    return StepOutcome::kRoot;
  }
  step_pending_ = false;
  t_ = t_end_of_step_;
  view(y_.get()) = y_end_;
  t_lo_ = t_;
  std::swap(g_lo_, g_end_);
  return outcome_at_end_;
}

std::string FlowSession::failure_text(const std::string& flag_name,
                                      bool root_function_failed) const {
  if (root_function_failed && !callbacks_.root_error.empty()) return root_failure_message();
  std::string text = library_ + " " + flag_name;
  if (!callbacks_.rhs_error.empty())
    text += " (" + callbacks_.rhs_error + ")";
  else if (!callbacks_.last_error.empty())
    text += " (" + callbacks_.last_error + ")";
  return text;
}

std::string FlowSession::root_failure_message() const {
  return library_ + " " + root_failure_flag_ + " (root function failed: " + callbacks_.root_error +
         ")";
}

Eigen::Map<const Eigen::VectorXd> FlowSession::state() const {
  return {N_VGetArrayPointer_Serial(y_.get()), size_};
}

Eigen::Map<const Eigen::VectorXd> FlowSession::interpolate(double t) const {
  dense_output(t, dense_.get());
  return {N_VGetArrayPointer_Serial(dense_.get()), size_};
}

std::vector<int> FlowSession::roots_found() const {
  if (own_root_search_) return found_;
  std::vector<int> found(static_cast<std::size_t>(callbacks_.num_roots), 0);
  if (callbacks_.num_roots > 0) library_roots_found(found.data());
  return found;
}

long FlowSession::root_evaluations() const {
  return own_root_search_ ? callbacks_.root_evaluations : library_root_evaluations();
}

std::unique_ptr<FlowSession> make_flow_session(int size, const EventDrivenOptions& options,
                                               FlowSession::Rhs rhs, FlowSession::Roots roots) {
  if (options.method == FlowMethod::kErk)
    return std::make_unique<ErkSession>(size, options, std::move(rhs), std::move(roots));
  if (options.method == FlowMethod::kOwnErk)
    return std::make_unique<OwnErkSession>(size, options, std::move(rhs), std::move(roots));
  return std::make_unique<CvodeSession>(size, options, std::move(rhs), std::move(roots));
}

}  // namespace impactbench::engines::event_driven
