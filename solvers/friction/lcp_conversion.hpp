#pragma once
// Friction contact as a linear complementarity problem, so that LCP solvers (Lemke, PGS) can
// solve it. Per contact the tangential impulse is spanned by k unit directions d_j of the
// tangent plane, r_t = Σ_j α_j d_j, α_j ≥ 0, and a slack β (the sliding speed) is added:
//   z_i = (r_n, α_1 … α_k, β),
//   0 ≤ r_n ⊥ u_n ≥ 0,
//   0 ≤ α_j ⊥ β + d_jᵀ u_t ≥ 0,
//   0 ≤ β   ⊥ μ r_n − Σ_j α_j ≥ 0.
// Sliding (u_t ≠ 0): β ≥ −d_jᵀu_t > 0 for some j, so Σα = μ r_n (on the boundary) and only
// the directions with d_jᵀu_t = −β (most opposed to u_t) carry impulse; sticking: β = 0 forces
// d_jᵀu_t ≥ 0 for all j, i.e. u_t = 0 when the d_j span the plane, with Σα ≤ μ r_n.
// Planar (dimension 2): k = 2, d = ±1; the set Σα ≤ μ r_n is exactly |r_t| ≤ μ r_n, so the LCP
// is exact. Spatial: k = cone_facets directions d_j = (cos 2πj/k, sin 2πj/k), an inscribed
// polygon of the friction disk (a faceted cone; error O(1 − cos π/k)).
// With r = T z (T maps z_i to (r_n, Σ α_j d_j)) the LCP is  w = (Tᵀ W T + C) z + Tᵀ q, where
// C holds the β coupling: C(α_j, β) = 1, C(β, r_n) = μ, C(β, α_j) = −1.
#include "solvers/friction/friction_problem.hpp"
#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers {

struct FrictionLcp {
  LcpProblem lcp;
  Eigen::SparseMatrix<double> to_impulse;  ///< T: r = T z
  int directions = 0;                      ///< k per contact
  int variables_per_contact() const { return directions + 2; }
};

/// Builds the LCP (dense for a dense W, sparse otherwise). Throws std::invalid_argument if
/// cone_facets < 3 for a spatial problem.
FrictionLcp friction_to_lcp(const FrictionProblem& problem, int cone_facets);

/// r = T z.
Eigen::VectorXd impulse_from_lcp(const FrictionLcp& conversion, VectorView z);

/// A z whose impulse T z is the projection of r on the faceted cone's generators (for warm
/// starts): r_t split on the two directions bounding its sector, β from the velocity of r.
Eigen::VectorXd lcp_point_from_impulse(const FrictionProblem& problem,
                                       const FrictionLcp& conversion, VectorView r);

}  // namespace impactbench::solvers
