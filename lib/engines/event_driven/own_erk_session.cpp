#include "lib/engines/event_driven/own_erk_session.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "lib/engines/event_driven/erk_table.hpp"
#include "lib/output/number_text.hpp"

namespace impactbench::engines::event_driven {
namespace {

// ARKODE's limit on error-test failures in one step (its maxnef).
constexpr int kMaxErrorTestFailures = 7;
constexpr double kSafety = 0.9, kMaxGrowth = 10.0, kMaxShrink = 0.2;
// The shrink after a right-hand side that is not finite (ARKODE's etacf).
constexpr double kShrinkAfterNonFinite = 0.25;

EventDrivenOptions with_own_root_search(EventDrivenOptions options) {
  options.dense_output_root_search = true;  // no library rootfinding here
  return options;
}

}  // namespace

struct OwnErkSession::Tableau {
  ButcherPair pair;
  Eigen::VectorXd error_coefficients;  // b − d
  double exponent = 0.0;               // 1 / (p̂ + 1)
};

OwnErkSession::OwnErkSession(int size, const EventDrivenOptions& options, Rhs rhs, Roots roots)
    : FlowSession(size, with_own_root_search(options), std::move(rhs), std::move(roots), "own_erk",
                  "root function failure"),
      relative_tolerance_(options.relative_tolerance),
      absolute_tolerance_(options.absolute_tolerance),
      initial_step_(options.initial_step),
      max_step_(options.max_step) {
  auto tableau = std::make_unique<Tableau>();
  tableau->pair = load_butcher_pair(options.erk_pair);
  tableau->error_coefficients = tableau->pair.b - tableau->pair.d;
  tableau->exponent = 1.0 / (tableau->pair.embedding_order + 1);
  tableau_ = std::move(tableau);
  f_.setZero(size);
  y_old_.setZero(size);
  stage_state_.setZero(size);
  error_.setZero(size);
  k_.setZero(size, tableau_->pair.stages());
  dense_.setZero(size, 4);
}

OwnErkSession::~OwnErkSession() = default;

void OwnErkSession::restart_library(double t0, int, double t_end) {
  carried_.restart(h_, h_last_);
  h_ = initial_step_;
  t_end_ = t_end;
  t_old_ = t0;
  have_f_ = false;
  have_step_ = false;
  non_finite_rejected_ = false;
  steps_ = 0;
  rhs_evaluations_ = 0;
}

void OwnErkSession::guards_armed() {
  carried_.guards_armed(h_);
}

int OwnErkSession::evaluate(double t, const Eigen::Ref<const Eigen::VectorXd>& y,
                            Eigen::Ref<Eigen::VectorXd> out) {
  ++rhs_evaluations_;
  const int flag = user_data()->evaluate_rhs(t, y, out);
  if (flag < 0) failure_ = failure_text("right-hand side failed", false);
  return flag;
}

double OwnErkSession::error_norm(const Eigen::Ref<const Eigen::VectorXd>& v,
                                 const Eigen::Ref<const Eigen::VectorXd>& y) const {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double scaled = v[i] / (relative_tolerance_ * std::abs(y[i]) + absolute_tolerance_);
    sum += scaled * scaled;
  }
  return std::sqrt(sum / static_cast<double>(v.size()));
}

double OwnErkSession::step_factor(double error) const {
  if (error == 0.0) return kMaxGrowth;  // the pair is exact here: grow as far as allowed
  const double factor = kSafety * std::pow(error, -tableau_->exponent);
  return factor >= kMaxShrink ? std::min(factor, kMaxGrowth) : kMaxShrink;  // NaN: the least
}

double OwnErkSession::estimated_first_step() const {
  const auto y = state();
  const double size = error_norm(y, y), rate = error_norm(f_, y);
  const double h = size < 1e-5 || rate < 1e-5 ? 1e-6 : 0.01 * size / rate;
  return std::min(h, t_end_ - t_);
}

OwnErkSession::StepOutcome OwnErkSession::library_step() {
  if (t_ >= t_end_) return StepOutcome::kReachedEnd;
  if (carried_.take_resume()) h_ = carried_.step();
  const ButcherPair& pair = tableau_->pair;
  const int stages = pair.stages();
  auto y = view(this->y());
  const auto failed_at = [&](const std::string& what) {
    failure_ = failure_text(what + " at t = " + output::number_text(t_), false);
    return StepOutcome::kFailure;
  };
  if (!have_f_) {
    const int flag = evaluate(t_, y, f_);
    if (flag < 0) return StepOutcome::kFailure;
    if (flag > 0) return failed_at("right-hand side not finite");
    have_f_ = true;
  }
  if (h_ <= 0.0) h_ = estimated_first_step();
  bool rejected = false;
  for (int failures = 0;;) {
    double h = max_step_ > 0.0 ? std::min(h_, max_step_) : h_;
    const bool to_end = t_ + h >= t_end_;
    if (to_end) h = t_end_ - t_;
    if (t_ + h == t_)
      return failed_at("step size " + output::number_text(h) + " too small" +
                       (non_finite_rejected_
                            ? " (the right-hand side is not finite just beyond; shorter steps "
                              "creep up to where it fails)"
                            : ""));
    // Stage i at y + Σ_j (h a_ij) k_j; with the pair's first same as last, the last stage's
    // state is the step's end.
    k_.col(0) = f_;
    bool finite = true;
    for (int i = 1; i < stages && finite; ++i) {
      stage_state_ = y;
      for (int j = 0; j < i; ++j)
        if (pair.a(i, j) != 0.0) stage_state_ += (h * pair.a(i, j)) * k_.col(j);
      const int flag = evaluate(t_ + pair.c[i] * h, stage_state_, k_.col(i));
      if (flag < 0) return StepOutcome::kFailure;
      finite = flag == 0;
    }
    double error = std::numeric_limits<double>::infinity();
    if (finite) {
      error_.setZero();
      for (int j = 0; j < stages; ++j)
        if (tableau_->error_coefficients[j] != 0.0)
          error_ += (h * tableau_->error_coefficients[j]) * k_.col(j);
      error = error_norm(error_, y);
    }
    if (!(error <= 1.0)) {  // also a NaN
      if (++failures >= kMaxErrorTestFailures) {
        const std::string tries = std::to_string(failures) +
                                  " times in one step (last h = " + output::number_text(h) + ")";
        if (!finite) return failed_at("right-hand side not finite " + tries);
        return failed_at(
            "error test failed " + tries +
            "; the flow is too stiff for an explicit method: run it with --option method=bdf");
      }
      rejected = true;
      non_finite_rejected_ = !finite;
      h_ = h * (finite ? step_factor(error) : kShrinkAfterNonFinite);
      continue;
    }
    y_old_ = y;
    t_old_ = t_;
    t_ = to_end ? t_end_ : t_ + h;
    if (pair.first_same_as_last) {
      y = stage_state_;
      f_ = k_.col(stages - 1);
    } else {
      for (int j = 0; j < stages; ++j)
        if (pair.b[j] != 0.0) y += (h * pair.b[j]) * k_.col(j);
      const int flag = evaluate(t_, y, f_);
      if (flag < 0) return StepOutcome::kFailure;
      if (flag > 0) return failed_at("right-hand side not finite");
    }
    have_step_ = true;
    ++steps_;
    h_last_ = h;
    prepare_dense_output(y);
    h_ = h * (rejected ? std::min(step_factor(error), 1.0) : step_factor(error));
    return to_end ? StepOutcome::kReachedEnd : StepOutcome::kStep;
  }
}

void OwnErkSession::dense_output(double t, N_Vector out) const {
  auto o = view(out);
  // The libraries' fuzz at the ends of a step: 100 units of round-off of its time and size.
  const double fuzz = 100.0 * DBL_EPSILON * (std::abs(t_) + std::abs(h_last_));
  if (t < (have_step_ ? t_old_ : t_) - fuzz || t > t_ + fuzz)
    throw std::logic_error("own_erk: dense output outside the last step");
  if (!have_step_) {
    o = state();
    return;
  }
  // y₀ + θ (Δ + (1 − θ) (r₂ + θ (r₃ + (1 − θ) E))): the cubic Hermite interpolant and the quartic
  // correction, nested so that every term is of the size of one step's change.
  const double theta = (t - t_old_) / h_last_, rest = 1.0 - theta;
  o = y_old_ + theta * (dense_.col(0) +
                        rest * (dense_.col(1) + theta * (dense_.col(2) + rest * dense_.col(3))));
}

void OwnErkSession::prepare_dense_output(const Eigen::Ref<const Eigen::VectorXd>& y_new) {
  // With Δ = y₁ − y₀, K₀ = h ẏ₀ (the first stage) and K₁ = h ẏ₁: the Hermite interpolant is
  // y₀ + θ Δ + θ (1 − θ) r₂ + θ² (1 − θ) r₃ with r₂ = K₀ − Δ and r₃ = Δ − K₁ − r₂ (its value and
  // slope at both ends); E = h Σ e_i k_i is the correction's (zero without one).
  const ButcherPair& pair = tableau_->pair;
  const double h = h_last_;
  dense_.col(0) = y_new - y_old_;
  dense_.col(1) = h * k_.col(0) - dense_.col(0);
  dense_.col(2) = dense_.col(0) - h * f_ - dense_.col(1);
  dense_.col(3).setZero();
  for (int i = 0; i < pair.quartic_correction.size(); ++i)
    if (pair.quartic_correction[i] != 0.0)
      dense_.col(3) += (h * pair.quartic_correction[i]) * k_.col(i);
}

void OwnErkSession::library_roots_found(int*) const {
  // Never asked: the roots are always located on the dense output (with_own_root_search).
}

}  // namespace impactbench::engines::event_driven
