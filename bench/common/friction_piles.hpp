#pragma once
// Friction-contact problems from piles of rigid bodies, the benchmark workload: disks (planar,
// dofs x, y, θ) or spheres (spatial, dofs v, ω) on a jittered lattice, each resting on the
// body below (or the ground) and touching its lattice neighbours with probability ½, so every
// contact touches at most two bodies. Bodies fall faster the higher they sit, so contacts are
// compressed; W = J M⁻¹ Jᵀ (usually rank-deficient, as in real piles) and q = J v_free.
#include <cstdint>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::bench {

/// About `contacts` contacts (exactly as many as the lattice produces, ≥ the request);
/// dense W when `dense`, block-sparse otherwise.
solvers::FrictionProblem pile_problem(int dimension, int contacts, bool dense,
                                      std::uint32_t seed = 42);

/// pile_problem(dimension, contacts, contacts <= 500) with the default seed, built once: the
/// benchmarks' workload (dense W up to 500 contacts, block-sparse beyond).
const solvers::FrictionProblem& cached_pile_problem(int dimension, int contacts);

}  // namespace impactbench::bench
