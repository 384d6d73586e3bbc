#include "solvers/friction/friction_residual.hpp"

#include <cmath>

#include "solvers/common/one_component_norm.hpp"
#include "solvers/common/select_bits.hpp"
#include "solvers/friction/coulomb_cone.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/factor_blocks_kernels.hpp"

namespace impactbench::solvers {
namespace {

// A planar contact's terms (d = 2), added to `sum_of_squares`: the general loop below in
// scalars, the same operations in the same order, so the same bits, without its small vectors
// (a Moreau–Jean solve evaluates this for every contact at every residual check).
[[gnu::always_inline]] inline void add_planar_contact_terms(double mu, double r_n, double r_t,
                                                            double u_n, double u_t,
                                                            double& sum_of_squares) {
  const double z_n = r_n - (u_n + mu * one_component_norm(u_t));
  const double z_t = r_t - u_t;
  // The tangent's norm as Eigen forms it, sqrt(z_t²).
  const ConeProjection projected = coulomb_cone_projection(mu, z_n, one_component_norm(z_t));
  const double difference_n = r_n - projected.normal;
  sum_of_squares += difference_n * difference_n;
  const double difference_t =
      r_t - select_bits(projected.apex, 0.0, projected.tangent_factor * z_t);
  sum_of_squares += difference_t * difference_t;
}

// A spatial contact's terms (d = 3): the vector form's operations in scalars, in its order
// (‖u_t‖² and ‖z_t‖² summed as Eigen sums the squares of two components), so the same bits,
// without the small vectors and the call to the projection (a sphere pile's nsgs solve spent
// about 5 % of its step in that call at its residual checks).
[[gnu::always_inline]] inline void add_spatial_contact_terms(double mu, const double* r,
                                                             const double* u,
                                                             double& sum_of_squares) {
  const double u_t_norm = std::sqrt(u[1] * u[1] + u[2] * u[2]);
  const double z_n = r[0] - (u[0] + mu * u_t_norm);  // z = r − (u + g(u))
  const double z_1 = r[1] - u[1];
  const double z_2 = r[2] - u[2];
  const ConeProjection projected =
      coulomb_cone_projection(mu, z_n, std::sqrt(z_1 * z_1 + z_2 * z_2));
  const double difference_n = r[0] - projected.normal;
  sum_of_squares += difference_n * difference_n;
  const double difference_1 =
      r[1] - select_bits(projected.apex, 0.0, projected.tangent_factor * z_1);
  sum_of_squares += difference_1 * difference_1;
  const double difference_2 =
      r[2] - select_bits(projected.apex, 0.0, projected.tangent_factor * z_2);
  sum_of_squares += difference_2 * difference_2;
}

// A contact's terms in dimension D (r and u its D components): the planar or spatial ones
// above, the projection being coulomb_cone.hpp's three cases.
template <int D>
[[gnu::always_inline]] inline void add_contact_terms(double mu, const double* r, const double* u,
                                                     double& sum_of_squares) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    add_planar_contact_terms(mu, r[0], r[1], u[0], u[1], sum_of_squares);
  else
    add_spatial_contact_terms(mu, r, u, sum_of_squares);
}

// The sums of every contact's squared terms, apart from the residual's divisor; not inlined,
// so that the loops keep their registers whatever the callers do with the sum.
[[gnu::noinline]] double sum_of_contact_terms(const FrictionProblem& problem, VectorView r,
                                              VectorView u) {
  double sum_of_squares = 0.0;
  factor_blocks::with_dimension(problem.dimension, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const auto first = static_cast<std::ptrdiff_t>(i) * D;
      add_contact_terms<D>(problem.mu(i), r.data() + first, u.data() + first, sum_of_squares);
    }
  });
  return sum_of_squares;
}

[[gnu::noinline]] double sum_of_factored_contact_terms(
    const FrictionProblem& problem, VectorView r, VectorView w,
    const std::vector<factor_blocks::RigidContactBlocks>* rigid) {
  double sum_of_squares = 0.0;
  factor_blocks::with_dimension(problem.dimension, [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const auto first = static_cast<std::ptrdiff_t>(i) * D;
      // H_i w into zeros, then q_i added: write_factored_contact_velocity's u_i.
      double u_i[D] = {};
      factor_blocks::add_rows<D>(problem.factor_blocks, rigid, i, w.data(), u_i);
      for (int k = 0; k < D; ++k) u_i[k] += problem.q(first + k);
      add_contact_terms<D>(problem.mu(i), r.data() + first, u_i, sum_of_squares);
    }
  });
  return sum_of_squares;
}

}  // namespace

double residual_scale(const FrictionProblem& problem) {
  const double q_norm = problem.q.norm();
  return q_norm > 0.0 ? q_norm : 1.0;
}

double friction_residual(const FrictionProblem& problem, VectorView r, VectorView u) {
  return friction_residual(problem, r, u, residual_scale(problem));
}

double friction_residual(const FrictionProblem& problem, VectorView r, VectorView u, double scale) {
  return std::sqrt(sum_of_contact_terms(problem, r, u)) / scale;
}

double factored_friction_residual(const FrictionProblem& problem, VectorView r, VectorView w,
                                  const std::vector<factor_blocks::RigidContactBlocks>* rigid) {
  return factored_friction_residual(problem, r, w, rigid, residual_scale(problem));
}

double factored_friction_residual(const FrictionProblem& problem, VectorView r, VectorView w,
                                  const std::vector<factor_blocks::RigidContactBlocks>* rigid,
                                  double scale) {
  return std::sqrt(sum_of_factored_contact_terms(problem, r, w, rigid)) / scale;
}

double friction_residual(const FrictionProblem& problem, VectorView r) {
  return friction_residual(problem, r, contact_velocity(problem, r));
}

}  // namespace impactbench::solvers
