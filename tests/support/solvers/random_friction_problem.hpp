#pragma once
// Random well-posed friction-contact problems for tests and benchmarks: rigid bodies (disks
// in the plane, spheres in space) with SPD mass matrices, contacts each touching one or two
// bodies at a random lever arm with a random orthonormal frame (normal first), and
//   W = J M⁻¹ Jᵀ   (block-sparse; positive definite when bodies outnumber contact rows),
//   q_n ∈ [−1, 0.3] (mostly approaching), q_t ∈ [−1, 1],  μ ∈ [0.1, 1].
#include <cstdint>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

struct RandomFrictionSpec {
  int contacts = 10;
  int bodies = 10;      ///< each contact picks two distinct bodies (or one and the ground)
  int dimension = 3;    ///< 2 planar disks (dofs x, y, θ), 3 spheres (v, ω)
  bool sparse = false;  ///< representation of W in the result
  std::uint32_t seed = 1;
  bool factored = false;  ///< W kept as H = J and A = M⁻¹Jᵀ (wins over `sparse`)
  /// With `factored`: the factors also by contact blocks (FactorBlocks), one block per body a
  /// contact touches, as the time stepper's assembly gives them.
  bool factor_blocks = false;
};

FrictionProblem random_friction_problem(const RandomFrictionSpec& spec);

/// The contact Jacobian row of direction e at lever arm p for one body (planar: e, p ∈ R²,
/// row [e_x, e_y, e·(−p_y, p_x)]; spatial: [eᵀ, (p × e)ᵀ]). Shared with the pile builders.
Eigen::VectorXd contact_jacobian_row(const Eigen::VectorXd& direction,
                                     const Eigen::VectorXd& lever_arm);

/// W = J M⁻¹ Jᵀ for a block-diagonal mass (per-body inverse blocks of size dofs × dofs).
Eigen::SparseMatrix<double, Eigen::RowMajor> delassus_from_jacobian(
    const Eigen::SparseMatrix<double>& jacobian, const Eigen::SparseMatrix<double>& inverse_mass);

}  // namespace impactbench::solvers
