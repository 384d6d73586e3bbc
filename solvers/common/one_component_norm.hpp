#pragma once
// The norm of a vector of one component, sqrt(x²) as Eigen forms it, without the square root:
// the planar friction cone's tangent is one component, and the sweeps and the residual wait on
// the square root's latency for every contact.
//
// Why |x| is the same number: with round to nearest, fl(x²) = x²(1 + δ), |δ| ≤ u = 2⁻⁵³, so
// √fl(x²) = |x|(1 + δ/2 + O(u²)) lies within |x|·u/2·(1 + u/4) of |x|. For |x| in [2^e, 2^(e+1))
// that is less than half of |x|'s unit in the last place, 2^(e−53) (and for |x| = 2^e the square
// is exact), so the correctly rounded square root is |x| itself. This needs x² to be a normal
// number: where it would underflow or overflow, the square root is taken as before.
#include <cmath>

namespace impactbench::solvers {

/// sqrt(x * x), to the bit, for every x (NaN stays NaN).
[[gnu::always_inline]] inline double one_component_norm(double x) {
  const double magnitude = std::abs(x);
  // x² is normal and finite for |x| in [2⁻⁵¹¹, 2⁵¹¹].
  if (magnitude >= 0x1p-511 && magnitude <= 0x1p+511) return magnitude;
  return std::sqrt(x * x);
}

}  // namespace impactbench::solvers
