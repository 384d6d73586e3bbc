#pragma once
// Location of the earliest decreasing zero crossing of a vector of guard functions g(t) within
// one integration step, from the values at both ends (CVODE's rootfinding contract: a
// component crosses in (t_lo, t_hi] when g_lo > 0 and g_hi <= 0).
//
// Illinois-modified secant steps on the component whose secant root comes first, as CVODE's
// cvRcheck3, with a shorter endgame: a secant point within half the tolerance of an end is
// moved to half the tolerance from it (CVODE moves it a tenth of the interval in, which takes
// one evaluation per decade when the secant lands on the root).
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace impactbench::engines::event_driven {

/// True when a component going from `lo` to `hi` crosses zero downwards.
inline bool crosses_downwards(double lo, double hi) {
  return lo > 0.0 && hi <= 0.0;
}

struct RootBracket {
  double t_lo = 0.0, t_hi = 0.0;  ///< t_hi − t_lo <= tolerance, or g(t_hi) has a zero
  Eigen::VectorXd g_lo, g_hi;     ///< guard values at both ends
  /// −1 for each component crossing in (t_lo, t_hi], 0 otherwise.
  std::vector<int> found;
};

/// g(t, out) writes the guard values at t. Requires a crossing between (t_lo, g_lo) and
/// (t_hi, g_hi); returns the final bracket, whose upper end is the root reported.
RootBracket locate_earliest_root(const std::function<void(double, Eigen::Ref<Eigen::VectorXd>)>& g,
                                 double t_lo, const Eigen::VectorXd& g_lo, double t_hi,
                                 const Eigen::VectorXd& g_hi, double tolerance);

}  // namespace impactbench::engines::event_driven
