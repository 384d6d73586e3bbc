#pragma once
// The LCP problem families and solver options of bench/lcp_bench.cpp, shared with
// bench/siconos_bench.cpp so that both run the very same problems with the same settings.
//   spd_dense       M = AᵀA + I dense (random_spd_problem), q ~ N(0, 1)
//   pmatrix_dense   non-symmetric P-matrix M = AᵀA + I + K − Kᵀ (pivoting and Newton only)
//   contact_sparse  M = J Jᵀ + 0.01 I sparse, 6 nonzeros per row of J
//                   (random_sparse_contact_problem)
//   contact_sparse_shuffled  the same with the contacts in random order
//   murty           Murty's problem as stated (upper triangular, q = −1): 2 Lemke pivots
//   murty_reversed  the same with indices reversed: 2^n Lemke pivots with our tie-break
#include <string>

#include "solvers/common/solver_types.hpp"
#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::bench {

/// The problem of `family` with `n` unknowns, built once and cached (fixed seed).
/// Throws std::invalid_argument for an unknown family.
const solvers::LcpProblem& lcp_family_problem(const std::string& family, int n);

/// Tolerance, iteration limit and relaxation of `solver` on `family` (n unknowns).
solvers::SolverOptions lcp_bench_options(const std::string& solver, const std::string& family,
                                         int n);

}  // namespace impactbench::bench
