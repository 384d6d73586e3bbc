#include "lib/engines/event_driven/root_search.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impactbench::engines::event_driven {
namespace {

// The crossing component whose secant root between lo and hi comes first (largest
// |g_hi| / |g_hi − g_lo|), with that fraction (0 for a zero at hi); −1 when none crosses.
Eigen::Index earliest_crossing(const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                               double& fraction) {
  Eigen::Index best = -1;
  fraction = -1.0;
  for (Eigen::Index i = 0; i < lo.size(); ++i) {
    if (!crosses_downwards(lo[i], hi[i])) continue;
    const double f = hi[i] / (hi[i] - lo[i]);
    if (f > fraction) {
      fraction = f;
      best = i;
    }
  }
  return best;
}

// The zero in (0, h) of the parabola through (0, g0), (h, gh) and (x3, g3) (the bracket's ends
// and a third point, times relative to the lower end), or NaN when there is none (a point
// coinciding with an end, or a root outside).
double parabola_root(double h, double g0, double gh, double x3, double g3) {
  const double slope = (gh - g0) / h;
  const double curvature = ((g3 - g0) / x3 - slope) / (x3 - h);
  // p(x) = a x² + b x + c
  const double a = curvature, b = slope - curvature * h, c = g0;
  if (!std::isfinite(a) || !std::isfinite(b)) return std::nan("");
  if (a == 0.0) return -c / b;
  const double disc = b * b - 4.0 * a * c;
  if (!(disc >= 0.0)) return std::nan("");
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  const double x1 = q / a, x2 = c / q;
  if (x1 > 0.0 && x1 < h) return x1;
  if (x2 > 0.0 && x2 < h) return x2;
  return std::nan("");
}

}  // namespace

RootBracket locate_earliest_root(const std::function<void(double, Eigen::Ref<Eigen::VectorXd>)>& g,
                                 double t_lo, const Eigen::VectorXd& g_lo, double t_hi,
                                 const Eigen::VectorXd& g_hi, double tolerance) {
  RootBracket b{t_lo, t_hi, g_lo, g_hi, {}};
  double fraction = 0.0;
  Eigen::Index imax = earliest_crossing(b.g_lo, b.g_hi, fraction);
  if (imax < 0) throw std::logic_error("locate_earliest_root: no crossing in the interval");
  Eigen::VectorXd g_mid(g_lo.size());
  int side = 0, side_before = -1;
  double alpha = 1.0;
  // The end replaced last, a third point for the parabola (none before the first evaluation).
  double t_old = std::nan("");
  Eigen::VectorXd g_old;
  // fraction 0: the only crossings are zeros at t_hi, the root reported.
  while (fraction > 0.0 && b.t_hi - b.t_lo > tolerance) {
    // Illinois: an end kept twice in a row has its value weighted down (up) by 2.
    alpha = side_before == side ? (side == 2 ? 2.0 * alpha : 0.5 * alpha) : 1.0;
    double t_mid =
        b.t_hi - (b.t_hi - b.t_lo) * b.g_hi[imax] / (b.g_hi[imax] - alpha * b.g_lo[imax]);
    // A smooth guard is near a parabola over a small interval (a constant-force flight: exactly
    // one), whose zero beats the secant; the Illinois secant stays the fallback.
    if (!std::isnan(t_old)) {
      const double x =
          parabola_root(b.t_hi - b.t_lo, b.g_lo[imax], b.g_hi[imax], t_old - b.t_lo, g_old[imax]);
      if (std::isfinite(x)) t_mid = b.t_lo + x;
    }
    const double half = 0.5 * tolerance;
    t_mid = std::clamp(t_mid, b.t_lo + half, b.t_hi - half);
    g(t_mid, g_mid);
    side_before = side;
    double f = 0.0;
    const Eigen::Index i_mid = earliest_crossing(b.g_lo, g_mid, f);
    if (i_mid >= 0) {  // a crossing in (t_lo, t_mid]: the root is there
      t_old = b.t_hi;
      g_old = b.g_hi;
      b.t_hi = t_mid;
      b.g_hi = g_mid;
      imax = i_mid;
      fraction = f;
      side = 1;
      continue;
    }
    t_old = b.t_lo;
    g_old = b.g_lo;
    b.t_lo = t_mid;  // no crossing before t_mid: every crossing lies in (t_mid, t_hi]
    b.g_lo = g_mid;
    side = 2;
  }
  b.found.assign(static_cast<std::size_t>(g_lo.size()), 0);
  for (Eigen::Index i = 0; i < g_lo.size(); ++i)
    if (crosses_downwards(b.g_lo[i], b.g_hi[i])) b.found[static_cast<std::size_t>(i)] = -1;
  return b;
}

}  // namespace impactbench::engines::event_driven
