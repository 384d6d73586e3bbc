#include "lib/engines/moreau_jean/free_motion.hpp"

#include <cmath>

#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

// f = S(q) u − H(q, v).
Eigen::VectorXd smooth_force(const model::LagrangianSystem<double>& system,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                             const Eigen::VectorXd& input) {
  Eigen::VectorXd f = -system.bias_forces(q, v);
  if (system.num_inputs() > 0) f += system.input_matrix(q) * input;
  return f;
}

}  // namespace

FreeMotion compute_free_motion(const model::LagrangianSystem<double>& system,
                               const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& input, double h,
                               const MoreauJeanOptions& options,
                               Eigen::SparseMatrix<double>* constant_mass_inverse) {
  const double theta = options.theta;
  FreeMotion out;
  if (options.forces == ForceTreatment::kExplicit) {
    const Eigen::VectorXd q_theta = system.integrate_position(q, v, theta * h);
    const Eigen::SparseMatrix<double> damping = system.damping_matrix(q_theta, v);
    const bool keep =
        constant_mass_inverse != nullptr && damping.size() == 0 && system.mass_matrix_is_constant();
    if (keep && constant_mass_inverse->size() > 0) {
      out.kept_inverse = constant_mass_inverse;
    } else {
      // Swapped in: Eigen 3.4's SparseMatrix copies on assignment, even from a temporary.
      Eigen::SparseMatrix<double> inverse =
          damping.size() == 0
              ? invert_block_diagonal(system.mass_matrix(q_theta))
              : invert_block_diagonal(system.mass_matrix(q_theta) + h * theta * damping,
                                      BlockFactorization::kLu);
      if (keep) {
        constant_mass_inverse->swap(inverse);
        out.kept_inverse = constant_mass_inverse;
      } else {
        out.inverse_iteration_matrix.swap(inverse);
      }
    }
    out.free_velocity = v + h * (out.inverse() * smooth_force(system, q_theta, v, input));
    return out;
  }

  const int nv = system.num_velocities();
  const Eigen::VectorXd f = smooth_force(system, q, v, input);
  // Central differences of f (K and C carry the opposite sign: they differentiate H − S u).
  Eigen::MatrixXd K(nv, nv), C(nv, nv);
  for (int j = 0; j < nv; ++j) {
    const double eps = options.jacobian_step * (1.0 + std::abs(v(j)));
    Eigen::VectorXd dv = Eigen::VectorXd::Zero(nv);
    dv(j) = 1.0;
    const double eps_q = options.jacobian_step;
    K.col(j) = -(smooth_force(system, system.integrate_position(q, dv, eps_q), v, input) -
                 smooth_force(system, system.integrate_position(q, dv, -eps_q), v, input)) /
               (2 * eps_q);
    C.col(j) = -(smooth_force(system, q, v + eps * dv, input) -
                 smooth_force(system, q, v - eps * dv, input)) /
               (2 * eps);
  }
  const Eigen::MatrixXd iteration =
      Eigen::MatrixXd(system.mass_matrix(q)) + h * theta * C + h * h * theta * theta * K;
  out.inverse_iteration_matrix =
      invert_block_diagonal(iteration.sparseView(), BlockFactorization::kLu);
  out.free_velocity = v + out.inverse_iteration_matrix * (h * f - h * h * theta * (K * v));
  return out;
}

}  // namespace impactbench::engines::moreau_jean
