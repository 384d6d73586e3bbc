#pragma once
// Reproducible LCP families shared by the tests and bench/lcp_bench.cpp. Each generator is a
// pure function of its size and seed (std::mt19937_64), so a failing case can be replayed.
#include <cstdint>

#include "solvers/lcp/lcp_problem.hpp"

namespace impactbench::solvers::lcp {

/// Murty's example: M upper triangular, 1 on the diagonal and 2 above it, q = −1. M is a
/// P-matrix (every principal minor is 1), and the unique solution is z = e_n (w = (1,…,1,0)).
LcpProblem murty_problem(int n);

/// Murty's example with the indices reversed (M lower triangular, 2 below the diagonal, q = −1);
/// the unique solution is z = e_1. With Lemke's lexicographic tie-break this is the ordering
/// that takes 2^n pivots (Murty 1978), while murty_problem(n) takes 2.
LcpProblem reversed_murty_problem(int n);

/// M = AᵀA + I with A_ij ~ N(0, 1/n) (symmetric positive definite, well conditioned),
/// q_i ~ N(0, 1).
LcpProblem random_spd_problem(int n, std::uint64_t seed);

/// M = AᵀA + I + (K − Kᵀ), A and K ~ N(0, 1/n): non-symmetric with positive definite
/// symmetric part, hence a P-matrix. q_i ~ N(0, 1).
LcpProblem random_nonsymmetric_pd_problem(int n, std::uint64_t seed);

/// M with off-diagonal entries U(−1, 1) and M_ii = Σ_j≠i |M_ij| + U(0.5, 1.5): strictly
/// row-diagonally dominant with positive diagonal, a non-symmetric P-matrix whose symmetric
/// part need not be positive definite. q_i ~ N(0, 1).
LcpProblem random_diagonally_dominant_problem(int n, std::uint64_t seed);

/// Degenerate positive semidefinite LCP with integer data: M = BᵀB where B (n/2 × n, entries
/// in {−1, 0, 1}) has duplicated columns, so M is singular with duplicated rows; q = w* − M z*
/// for a complementary pair (z*, w*) in which some indices have z*_i = w*_i = 0, some q_i = 0,
/// and duplicated indices have equal q_i (ties in every ratio test). Solvable by construction.
LcpProblem degenerate_psd_problem(int n, std::uint64_t seed);

/// How the rows of a contact problem are ordered: by the first body they touch (as a broad
/// phase that sweeps space lists them; neighbouring rows then share columns) or at random.
enum class ContactOrder { kByBody, kRandom };

/// Contact-like sparse LCP, M = J Jᵀ + δ I stored sparse: `n` contacts between bodies with 3
/// velocity coordinates each (n/2 bodies on a line), every contact row of J touching two bodies
/// at most `window` apart (6 nonzeros, entries N(0, 1)); about 9 nonzeros per row of M.
/// q_i ~ U(−1, 1).
LcpProblem random_sparse_contact_problem(int n, std::uint64_t seed, double delta = 1e-2,
                                         int window = 4,
                                         ContactOrder order = ContactOrder::kByBody);

}  // namespace impactbench::solvers::lcp
