#include "lib/engines/moreau_jean/free_motion.hpp"

#include <cmath>

#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

// f = S(q) u − H(q, v).
Eigen::VectorXd smooth_force(const model::LagrangianSystem<double>& system,
                             const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                             const Eigen::VectorXd& input) {
  Eigen::VectorXd f;
  model::write_free_force(system, q, v, input, f);
  return f;
}

}  // namespace

FreeMotion compute_free_motion(const model::LagrangianSystem<double>& system,
                               const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                               const Eigen::VectorXd& input, double h,
                               const MoreauJeanOptions& options,
                               Eigen::SparseMatrix<double>* constant_mass_inverse) {
  FreeMotion out;
  compute_free_motion(system, q, v, input, h, options, constant_mass_inverse, out);
  return out;
}

void compute_free_motion(const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& v, const Eigen::VectorXd& input, double h,
                         const MoreauJeanOptions& options,
                         Eigen::SparseMatrix<double>* constant_mass_inverse, FreeMotion& out) {
  const double theta = options.theta;
  out.kept_inverse = nullptr;
  if (options.forces == ForceTreatment::kExplicit) {
    system.write_integrated_position(q, v, theta * h, out.q_theta);
    const Eigen::VectorXd& q_theta = out.q_theta;
    // Asked only of a system that has one: even an empty Eigen sparse matrix allocates.
    if (system.has_damping_matrix()) out.damping = system.damping_matrix(q_theta, v);
    const bool damped = system.has_damping_matrix() && out.damping.size() != 0;
    const Eigen::SparseMatrix<double>& damping = out.damping;
    const bool keep =
        constant_mass_inverse != nullptr && !damped && system.mass_matrix_is_constant();
    if (!keep || constant_mass_inverse->size() == 0) {
      // Formed in place, into M⁻¹ kept by the caller or into out's storage.
      Eigen::SparseMatrix<double>& inverse =
          keep ? *constant_mass_inverse : out.inverse_iteration_matrix;
      system.write_mass_matrix(q_theta, out.mass_matrix);
      if (!damped)
        invert_block_diagonal(out.mass_matrix, BlockFactorization::kCholesky, inverse);
      else
        invert_block_diagonal(out.mass_matrix + h * theta * damping, BlockFactorization::kLu,
                              inverse);
    }
    if (keep) out.kept_inverse = constant_mass_inverse;
    // v + h Â⁻¹ f, in out's storage. Eigen folds h into the sparse factor, (h Â⁻¹) f, whether
    // the product stands alone or inside v + h (Â⁻¹ f): the same sums, so the same bits (h times
    // a product formed first rounds differently where a row has several entries).
    model::write_free_force(system, q_theta, v, input, out.force);
    out.velocity_change.noalias() = h * (out.inverse() * out.force);
    out.free_velocity = v + out.velocity_change;
    return;
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
  invert_block_diagonal(iteration.sparseView(), BlockFactorization::kLu,
                        out.inverse_iteration_matrix);
  out.free_velocity = v + out.inverse_iteration_matrix * (h * f - h * h * theta * (K * v));
}

}  // namespace impactbench::engines::moreau_jean
