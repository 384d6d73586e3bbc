#include "lib/sensitivity/trajectory_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

#include "lib/output/number_text.hpp"

namespace impactbench::sensitivity {
namespace {

constexpr double kStageOffset[4] = {0.0, 0.5, 0.5, 1.0};
/// The graded end of a turning-slip segment (LinearisedSegment::times): it starts 32 uniform
/// steps before the event, each step covers 1/32 of the time left (RK4's relative error per
/// step ~(1/32)⁵/120 ≈ 2e-10 where h‖A‖ ≈ 1/32), and it stops 2⁻²⁴ of a uniform step
/// (~1e-10 s) short of the event.
constexpr int kGradedSteps = 32;
constexpr double kGradedStop = 0x1p-24;
/// A segment after a spatial stick→slip onset (LinearisedSegment::times). It starts with
/// L-stable Rosenbrock steps (ROS2, γ = 1 + 1/√2, order 2, with the exact Jacobian A) of
/// h = kOnsetStepRatio × max(t − t*, kOnsetFirstStep × the uniform step): the fast decay
/// across the slip direction is damped whatever h‖A‖, and the steps grow geometrically from
/// the onset. Once the stiffness is past its peak and RK4 would be stable on kImplicitReach⁻¹
/// of such a step (h ≤ kStiffStep/‖A‖∞, where its amplification at h·λ = −1 is 0.375 against
/// e⁻¹ = 0.368) RK4 takes over with that bound, which relaxes like (t − t*)², until the uniform
/// step; at most kMaxOnsetSteps steps.
constexpr double kRosenbrockGamma = 1.0 + 0.70710678118654752440;
constexpr double kOnsetStepRatio = 0.02;
constexpr double kOnsetFirstStep = 1e-4;
constexpr double kImplicitReach = 50.0;
constexpr double kStiffStep = 1.0;
constexpr int kMaxOnsetSteps = 2000000;

/// Cubic Hermite interpolation on [0, h] at s ∈ [0, h] of values y0, y1 and slopes d0, d1.
template <typename T>
T hermite(const T& y0, const T& d0, const T& y1, const T& d1, double h, double s) {
  const double r = s / h;
  const double r2 = r * r, r3 = r2 * r;
  return (2 * r3 - 3 * r2 + 1) * y0 + (r3 - 2 * r2 + r) * h * d0 + (-2 * r3 + 3 * r2) * y1 +
         (r3 - r2) * h * d1;
}

/// Start time and size of step k of a segment (uniform, or the graded grid `times`).
double step_time(const LinearisedSegment& seg, int k) {
  return seg.times.empty() ? seg.t_begin + k * seg.h : seg.times[static_cast<std::size_t>(k)];
}
double step_size(const LinearisedSegment& seg, int k) {
  return seg.times.empty()
             ? seg.h
             : seg.times[static_cast<std::size_t>(k) + 1] - seg.times[static_cast<std::size_t>(k)];
}

/// Whether a macro event ends a spatial slip at ‖ζ_t‖ = 0 (the segment before it needs the
/// graded grid of LinearisedSegment::times).
bool has_turning_slip_event(const HybridModel& model, const NominalEvent& event, GuardKind kind) {
  if (!model.slip_direction_turns()) return false;
  for (const MicroEvent& me : event.micro_events)
    if (me.kind == kind) return true;
  return false;
}
bool ends_turning_slip(const HybridModel& model, const NominalEvent& event) {
  return has_turning_slip_event(model, event, GuardKind::kSlipToStick);
}
/// Whether a macro event starts a spatial slip from ‖ζ_t‖ = 0 (the segment after it needs the
/// stiffness-limited steps of LinearisedSegment::times).
bool starts_turning_slip(const HybridModel& model, const NominalEvent& event) {
  return has_turning_slip_event(model, event, GuardKind::kStickToSlip);
}

/// One ROS2 step of Ż = A(t) Z + W(t) (the Rosenbrock steps of a slip onset): A at the step's
/// start (slot 4k) as the method's Jacobian, A and W at its end stage (slot 4k + 1).
template <typename T, typename Forcing>
T linear_rosenbrock_step(const LinearisedSegment& seg, int k, const T& z, const Forcing& forcing) {
  const double h = step_size(seg, k);
  const double t = step_time(seg, k);
  const Eigen::MatrixXd& A0 = seg.A[static_cast<std::size_t>(4 * k)];
  const Eigen::MatrixXd& A1 = seg.A[static_cast<std::size_t>(4 * k + 1)];
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Eigen::MatrixXd::Identity(A0.rows(), A0.cols()) -
                                                (kRosenbrockGamma * h) * A0);
  const T k1 = lu.solve(T(A0 * z + forcing(4 * k, t)));
  const T k2 = lu.solve(T(A1 * (z + h * k1) + forcing(4 * k + 1, t + h) - 2.0 * k1));
  return z + (1.5 * h) * k1 + (0.5 * h) * k2;
}

/// One step of Ż = A(t) Z + W(t) on segment `seg`, step k, with the stored stage Jacobians:
/// RK4, or ROS2 where the segment's step is a Rosenbrock step. `forcing(stage_index, t)`
/// returns W at the stage (B v for vectors, B V for matrices).
template <typename T, typename Forcing>
T linear_flow_step(const LinearisedSegment& seg, int k, const T& z, const Forcing& forcing) {
  if (!seg.rosenbrock.empty() && seg.rosenbrock[static_cast<std::size_t>(k)])
    return linear_rosenbrock_step(seg, k, z, forcing);
  const double h = step_size(seg, k);
  const double t = step_time(seg, k);
  const int base = 4 * k;
  const T k1 = seg.A[base] * z + forcing(base, t);
  const T k2 = seg.A[base + 1] * (z + 0.5 * h * k1) + forcing(base + 1, t + 0.5 * h);
  const T k3 = seg.A[base + 2] * (z + 0.5 * h * k2) + forcing(base + 2, t + 0.5 * h);
  const T k4 = seg.A[base + 3] * (z + h * k3) + forcing(base + 3, t + h);
  return z + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// A and B at grid point k (k = steps: the end point).
int grid_index(int k) {
  return 4 * k;
}

/// RK4 stages 1–3 of the nominal's step from x at t (stage 0, of rate f0, already stored):
/// their A and B into `seg`; returns the state at t + h.
Eigen::VectorXd rk4_step_after_start(const HybridModel& model, const NominalTrajectory& nominal,
                                     LinearisedSegment& seg, const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& f0, double t, double h) {
  const int m = model.input_size();
  Eigen::VectorXd slope[4];
  slope[0] = f0;
  for (int s = 1; s < 4; ++s) {
    const Eigen::VectorXd xs = x + kStageOffset[s] * h * slope[s - 1];
    const FlowLinearisation lin =
        model.linearise_flow(seg.mode, xs, nominal.input_at(t + kStageOffset[s] * h, m));
    slope[s] = lin.f;
    seg.A.push_back(lin.A);
    seg.B.push_back(lin.B);
  }
  return x + (h / 6.0) * (slope[0] + 2.0 * slope[1] + 2.0 * slope[2] + slope[3]);
}

/// The segment's last grid point: the state x at t_last with its rate, A and B.
void close_segment(const HybridModel& model, const NominalTrajectory& nominal,
                   LinearisedSegment& seg, const Eigen::VectorXd& x, double t_last) {
  seg.alpha.push_back(x);
  const FlowLinearisation end =
      model.linearise_flow(seg.mode, x, nominal.input_at(t_last, model.input_size()));
  seg.alpha_rate.push_back(end.f);
  seg.A.push_back(end.A);
  seg.B.push_back(end.B);
}

}  // namespace

TrajectorySensitivity::TrajectorySensitivity(const HybridModel& model, NominalTrajectory nominal,
                                             SensitivityOptions options)
    : model_(model), nominal_(std::move(nominal)), options_(options) {
  if (!(options_.max_step > 0.0 && std::isfinite(options_.max_step)))
    throw std::invalid_argument("TrajectorySensitivity: max_step must be positive and finite");
  nominal_.validate(model_.state_size(), model_.num_contacts());
  const int m = model_.input_size();
  Eigen::VectorXd x = nominal_.x0;
  HybridMode mode = nominal_.mode0;
  double t = nominal_.t_begin;
  bool onset = false;
  for (const NominalEvent& event : nominal_.events) {
    segments_.push_back(
        linearise_segment(mode, t, event.time, x, ends_turning_slip(model_, event), onset));
    onset = starts_turning_slip(model_, event);
    events_.emplace_back(model_, mode, event.micro_events, segments_.back().alpha.back(),
                         nominal_.input_at(event.time, m), nominal_.input_rate_at(event.time, m));
    mode = events_.back().mode_after();
    x = event.x_plus ? *event.x_plus : events_.back().x_plus();
    t = event.time;
  }
  segments_.push_back(linearise_segment(mode, t, nominal_.t_end, x, false, onset));
}

LinearisedSegment TrajectorySensitivity::linearise_segment(const HybridMode& mode, double t0,
                                                           double t1, const Eigen::VectorXd& x0,
                                                           bool graded_end,
                                                           bool stiff_start) const {
  const int m = model_.input_size();
  LinearisedSegment seg;
  seg.mode = mode;
  seg.t_begin = t0;
  seg.t_end = t1;
  seg.steps = std::max(1, static_cast<int>(std::ceil((t1 - t0) / options_.max_step - 1e-9)));
  seg.h = (t1 - t0) / seg.steps;
  if (stiff_start) return linearise_stiff_start(std::move(seg), x0, graded_end);
  if (graded_end) {
    const int uniform = std::max(0, seg.steps - kGradedSteps);
    for (int k = 0; k <= uniform; ++k) seg.times.push_back(t0 + k * seg.h);
    while (t1 - seg.times.back() > kGradedStop * seg.h)
      seg.times.push_back(seg.times.back() + (t1 - seg.times.back()) / kGradedSteps);
    seg.steps = static_cast<int>(seg.times.size()) - 1;
  }
  seg.alpha.reserve(seg.steps + 1);
  seg.A.reserve(4 * seg.steps + 1);
  seg.B.reserve(4 * seg.steps + 1);
  Eigen::VectorXd x = x0;
  for (int k = 0; k < seg.steps; ++k) {
    const double t = step_time(seg, k);
    const double h = step_size(seg, k);
    seg.alpha.push_back(x);
    const FlowLinearisation start = model_.linearise_flow(mode, x, nominal_.input_at(t, m));
    seg.alpha_rate.push_back(start.f);
    seg.A.push_back(start.A);
    seg.B.push_back(start.B);
    x = rk4_step_after_start(model_, nominal_, seg, x, start.f, t, h);
  }
  close_segment(model_, nominal_, seg, x, seg.times.empty() ? t1 : seg.times.back());
  return seg;
}

// The grid is made while integrating: Rosenbrock steps growing with the time since the onset,
// then RK4 steps bounded by ‖A‖∞ at their start (stage 0), then uniform ones; a graded end as
// in linearise_segment.
LinearisedSegment TrajectorySensitivity::linearise_stiff_start(LinearisedSegment seg,
                                                               const Eigen::VectorXd& x0,
                                                               bool graded_end) const {
  const int m = model_.input_size();
  const double t0 = seg.t_begin, t1 = seg.t_end;
  const double stop = graded_end ? kGradedStop * seg.h : 0.0;
  seg.times.assign(1, t0);
  Eigen::VectorXd x = x0;
  bool implicit = true;
  double peak_ratio = 0.0;
  while (t1 - seg.times.back() > stop) {
    const double t = seg.times.back();
    if (seg.times.size() > kMaxOnsetSteps)
      throw std::runtime_error(
          "TrajectorySensitivity: the slip after the stick-to-slip onset at t = " +
          output::number_text(t0) + " s needs more than " + std::to_string(kMaxOnsetSteps) +
          " steps before t = " + output::number_text(t) + " s");
    seg.alpha.push_back(x);
    const FlowLinearisation start = model_.linearise_flow(seg.mode, x, nominal_.input_at(t, m));
    seg.alpha_rate.push_back(start.f);
    const double rk4_bound = kStiffStep / start.A.cwiseAbs().rowwise().sum().maxCoeff();
    const double growing = kOnsetStepRatio * std::max(t - t0, kOnsetFirstStep * seg.h);
    // The ratio rises from the onset while the smoothing bounds ‖A‖, then falls like
    // 1/(t − t*); switched past its peak (a quarter of it, clear of step-to-step noise), or at
    // once where RK4 is stable on the Rosenbrock step itself.
    const double ratio = growing / rk4_bound;
    peak_ratio = std::max(peak_ratio, ratio);
    if (implicit && (ratio <= 1.0 || (ratio <= kImplicitReach && ratio <= 0.25 * peak_ratio)))
      implicit = false;
    double h = std::min(seg.h, implicit ? growing : rk4_bound);
    if (graded_end && t1 - t <= kGradedSteps * seg.h) h = std::min(h, (t1 - t) / kGradedSteps);
    if (t1 - (t + h) < 1e-3 * h) h = t1 - t;
    seg.rosenbrock.push_back(implicit ? 1 : 0);
    seg.A.push_back(start.A);
    seg.B.push_back(start.B);
    if (implicit) {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Eigen::MatrixXd::Identity(x.size(), x.size()) -
                                                    (kRosenbrockGamma * h) * start.A);
      const Eigen::VectorXd k1 = lu.solve(start.f);
      const FlowLinearisation end =
          model_.linearise_flow(seg.mode, x + h * k1, nominal_.input_at(t + h, m));
      const Eigen::VectorXd k2 = lu.solve(Eigen::VectorXd(end.f - 2.0 * k1));
      seg.A.push_back(end.A);
      seg.B.push_back(end.B);
      seg.A.emplace_back();  // slots 4k + 2, 4k + 3: not used by a Rosenbrock step
      seg.B.emplace_back();
      seg.A.emplace_back();
      seg.B.emplace_back();
      x += (1.5 * h) * k1 + (0.5 * h) * k2;
    } else {
      x = rk4_step_after_start(model_, nominal_, seg, x, start.f, t, h);
    }
    seg.times.push_back(h == t1 - t ? t1 : t + h);
  }
  seg.steps = static_cast<int>(seg.times.size()) - 1;
  close_segment(model_, nominal_, seg, x, seg.times.back());
  return seg;
}

Eigen::VectorXd TrajectorySensitivity::input_perturbation(const InputFunction& v, double t) const {
  const int m = model_.input_size();
  if (!v) return Eigen::VectorXd::Zero(m);
  Eigen::VectorXd value = v(t);
  if (value.size() != m)
    throw std::invalid_argument("TrajectorySensitivity: v(t) has " + std::to_string(value.size()) +
                                " entries, expected " + std::to_string(m));
  return value;
}

Eigen::VectorXd TrajectorySensitivity::nominal_state(double t) const {
  if (!(t >= nominal_.t_begin && t <= nominal_.t_end))
    throw std::invalid_argument("TrajectorySensitivity: t outside the nominal's time range");
  for (const LinearisedSegment& seg : segments_) {
    if (t > seg.t_end) continue;
    int k = std::min(seg.steps - 1, static_cast<int>((t - seg.t_begin) / seg.h));
    if (!seg.times.empty())
      k = std::clamp(static_cast<int>(std::upper_bound(seg.times.begin(), seg.times.end(), t) -
                                      seg.times.begin()) -
                         1,
                     0, seg.steps - 1);
    return hermite<Eigen::VectorXd>(seg.alpha[k], seg.alpha_rate[k], seg.alpha[k + 1],
                                    seg.alpha_rate[k + 1], step_size(seg, k),
                                    t - step_time(seg, k));
  }
  return segments_.back().alpha.back();
}

std::vector<Eigen::VectorXd> TrajectorySensitivity::perturbation(
    const Eigen::VectorXd& z0, const InputFunction& v, const std::vector<double>& times) const {
  if (z0.size() != model_.state_size() || !z0.allFinite())
    throw std::invalid_argument("TrajectorySensitivity: z0 must be finite with " +
                                std::to_string(model_.state_size()) + " entries");
  for (std::size_t i = 0; i < times.size(); ++i)
    if (!(times[i] >= nominal_.t_begin && times[i] <= nominal_.t_end) ||
        (i > 0 && times[i] < times[i - 1]))
      throw std::invalid_argument(
          "TrajectorySensitivity: output times must be non-decreasing within the nominal's range");
  std::vector<Eigen::VectorXd> out;
  out.reserve(times.size());
  std::size_t next = 0;
  Eigen::VectorXd z = z0;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const LinearisedSegment& seg = segments_[s];
    const auto forcing = [&](int index, double t) -> Eigen::VectorXd {
      return seg.B[index] * input_perturbation(v, t);
    };
    Eigen::VectorXd rate = seg.A[0] * z + forcing(0, seg.t_begin);
    for (int k = 0; k < seg.steps && next < times.size(); ++k) {
      const double t = step_time(seg, k);
      const double h = step_size(seg, k);
      const Eigen::VectorXd z_next = linear_flow_step(seg, k, z, forcing);
      const int g = grid_index(k + 1);
      const Eigen::VectorXd rate_next = seg.A[g] * z_next + forcing(g, t + h);
      const double t_next = k + 1 == seg.steps ? seg.t_end : t + h;
      while (next < times.size() && times[next] <= t_next) {
        out.push_back(hermite(z, rate, z_next, rate_next, h, times[next] - t));
        ++next;
      }
      z = z_next;
      rate = rate_next;
    }
    if (next == times.size()) break;
    if (s < events_.size()) z = events_[s].apply(z, input_perturbation(v, seg.t_end));
  }
  return out;
}

EndPointSensitivity TrajectorySensitivity::end_point_sensitivity(
    const InputBasis& basis, const Eigen::VectorXd& cone_z0, const Eigen::VectorXd& cone_p) const {
  const int n = model_.state_size();
  const int m = model_.input_size();
  const Eigen::MatrixXd first = basis ? basis(nominal_.t_begin) : Eigen::MatrixXd::Zero(m, 0);
  const Eigen::Index p = first.cols();
  if (first.rows() != m)
    throw std::invalid_argument("TrajectorySensitivity: the input basis must have " +
                                std::to_string(m) + " rows");
  const auto basis_at = [&](double t) -> Eigen::MatrixXd {
    return basis ? basis(t) : Eigen::MatrixXd::Zero(m, 0);
  };
  // Columns: [Φ | Ψ] of (z0, p); the direction (cone_z0, cone_p) selects each event's order.
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(n, n + p);
  Z.leftCols(n).setIdentity();
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(n + p);
  if (cone_z0.size() == n) direction.head(n) = cone_z0;
  if (cone_p.size() == p) direction.tail(p) = cone_p;
  EndPointSensitivity out;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const LinearisedSegment& seg = segments_[s];
    const auto forcing = [&](int index, double t) -> Eigen::MatrixXd {
      Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, n + p);
      if (p > 0) w.rightCols(p) = seg.B[index] * basis_at(t);
      return w;
    };
    for (int k = 0; k < seg.steps; ++k) Z = linear_flow_step(seg, k, Z, forcing);
    if (s < events_.size()) {
      const Eigen::MatrixXd V = basis_at(seg.t_end);
      const Eigen::VectorXd zd = Z * direction;
      const Eigen::VectorXd vd =
          p > 0 ? Eigen::VectorXd(V * direction.tail(p)) : Eigen::VectorXd::Zero(m);
      const ComposedGain gain = events_[s].gain_of_order(events_[s].order_for(zd, vd));
      out.orders.push_back(gain.order);
      Eigen::MatrixXd next = gain.Gz * Z;
      if (p > 0) next.rightCols(p) += gain.Gv * V;
      Z = next;
    }
  }
  out.state = Z.leftCols(n);
  out.input = Z.rightCols(p);
  return out;
}

}  // namespace impactbench::sensitivity
