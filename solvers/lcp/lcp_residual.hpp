#pragma once
// The single place where w = M z + q and the natural-map residual ‖min(z, w)‖∞ are computed, so
// that the driver, the iterative methods' stopping tests and the benchmarks agree exactly.
#include <Eigen/Core>

#include "solvers/common/capacity_vector.hpp"

#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers::lcp {

/// w = M z + q, with M dense or sparse as stored in the problem.
CapacityVector lcp_velocity(const LcpProblem& problem, VectorView z);
/// The same w into `w`, whose storage is reused when it has the size already.
void write_lcp_velocity(const LcpProblem& problem, VectorView z, CapacityVector& w);

/// ‖min(z, w)‖∞: zero exactly when 0 ≤ z ⊥ w ≥ 0. NaN in z or w gives NaN (never "converged").
double natural_map_residual(VectorView z, VectorView w);

}  // namespace impactbench::solvers::lcp
