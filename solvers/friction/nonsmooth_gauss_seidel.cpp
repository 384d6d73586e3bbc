// nsgs: nonsmooth Gauss–Seidel. Contact by contact, the local problem
//   u_i = W_ii r_i + b_i,  b_i = q_i + Σ_{j≠i} W_ij r_j   (current r)
// is solved exactly (single_contact_solver), then the global residual decides convergence
// (evaluated every sweep while the solve may be near convergence, see below). A factored
// problem (W = H A) is swept through the velocity A r instead of W's rows.
#include <algorithm>
#include <cmath>

#include "solvers/common/thread_kept.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/factor_blocks_kernels.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"
#include "solvers/friction/single_contact_solver.hpp"

namespace impactbench::solvers::friction_detail {

namespace {

// Planar contacts prepared once per solve (nsgs); null: each local problem solved from W_ii.
using PreparedContacts = std::vector<PreparedPlanarContact>;
// Spatial contacts prepared once per solve, for the sweep over factor blocks.
using PreparedSpatialContacts = std::vector<PreparedSpatialContact>;

// The sweep of both forms: contact by contact, b_i = (W r)_i − W_ii r_i + q_i with (W r)_i from
// `row_times(i)` (the current r), the local problem solved exactly, then `changed(i, k, Δr_ik)`
// for each component that moved, before r_i is written back.
template <typename RowTimes, typename Changed>
bool gauss_seidel_sweep(const FrictionProblem& problem,
                        const std::vector<LocalMatrix>& diagonal_blocks,
                        const PreparedContacts* prepared, CapacityVector& r, RowTimes&& row_times,
                        Changed&& changed) {
  const int d = problem.dimension;
  bool all_exact = true;
  for (int i = 0; i < problem.num_contacts(); ++i) {
    const LocalMatrix& w_ii = diagonal_blocks[static_cast<std::size_t>(i)];
    const LocalVector r_old = contact_part(r, i, d);
    const LocalVector b_i = row_times(i) - w_ii * r_old + contact_part(problem.q, i, d);
    LocalVector r_i = r_old;
    if (prepared != nullptr && d == 2)
      all_exact = solve_prepared_planar_contact((*prepared)[static_cast<std::size_t>(i)], b_i(0),
                                                b_i(1), r_i(0), r_i(1)) &&
                  all_exact;
    else
      all_exact = solve_single_contact(w_ii, b_i, problem.mu(i), r_i) && all_exact;
    for (int k = 0; k < d; ++k)
      if (r_i(k) != r_old(k)) changed(i, k, r_i(k) - r_old(k));
    contact_part(r, i, d) = r_i;
  }
  return all_exact;
}

// A formed W (dense or sparse) is swept through its rows.
bool formed_gauss_seidel_sweep(const FrictionProblem& problem,
                               const std::vector<LocalMatrix>& diagonal_blocks,
                               const PreparedContacts* prepared, CapacityVector& r) {
  return gauss_seidel_sweep(
      problem, diagonal_blocks, prepared, r, [&](int i) { return block_row_times(problem, i, r); },
      [](int, int, double) {});
}

// A factored problem (W = H A) is swept through the velocity w = A r: (W r)_i = H_i w, and w
// follows every change of r_i along A's columns of contact i. Each contact costs its rows of H
// and columns of A, as in the impulse-based engines; W is never formed.
bool factored_gauss_seidel_sweep(const FrictionProblem& problem,
                                 const std::vector<LocalMatrix>& diagonal_blocks,
                                 const PreparedContacts* prepared, CapacityVector& r,
                                 CapacityVector& w) {
  using RowIterator = Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator;
  using ColumnIterator = Eigen::SparseMatrix<double>::InnerIterator;
  const int d = problem.dimension;
  const auto row_times = [&](int i) {
    LocalVector product(d);
    for (int k = 0; k < d; ++k) {
      double sum = 0.0;
      for (RowIterator it(problem.factor_H, i * d + k); it; ++it) sum += it.value() * w(it.col());
      product(k) = sum;
    }
    return product;
  };
  const auto changed = [&](int i, int k, double change) {
    for (ColumnIterator it(problem.factor_A, i * d + k); it; ++it)
      w(it.row()) += it.value() * change;
  };
  return gauss_seidel_sweep(problem, diagonal_blocks, prepared, r, row_times, changed);
}

// The same sweep over the factors by contact blocks (FactorBlocks, factor_blocks_kernels.hpp),
// D components per contact: each contact's rows of H and columns of A read in order from one
// array, w by range, the local vectors of fixed size. W_ii r_i is summed as Eigen's
// coefficient-wise product, so r is the sparse sweep's to the bit. W_ii is read from the
// contact's prepared record, which holds a copy of it: a sweep reads one record per contact
// instead of two.
template <int D>
bool blocked_gauss_seidel_sweep(const FrictionProblem& problem, const PreparedContacts& prepared,
                                const PreparedSpatialContacts& prepared_spatial,
                                const std::vector<factor_blocks::RigidContactBlocks>& rigid,
                                CapacityVector& r, CapacityVector& w) {
  bool all_exact = true;
  // b_i = (W r)_i − W_ii r_i + q_i, W_ii(row, col) from `w_ii`.
  const auto local_b = [&](int i, const double* row_times, const double* r_i, auto&& w_ii,
                           double* b_i) {
    const double* q_i = problem.q.data() + static_cast<std::ptrdiff_t>(i) * D;
    for (int row = 0; row < D; ++row) {
      double own = w_ii(row, 0) * r_i[0];
      for (int col = 1; col < D; ++col) own += w_ii(row, col) * r_i[col];
      b_i[row] = (row_times[row] - own) + q_i[row];
    }
  };
  const auto solve_locally = [&](int i, const double* row_times, const double* r_i, double* r_new) {
    double b_i[D];
    if constexpr (D == 2) {
      const PreparedPlanarContact& contact = prepared[static_cast<std::size_t>(i)];
      local_b(
          i, row_times, r_i, [&](int row, int col) { return contact.a[row * 2 + col]; }, b_i);
      all_exact =
          solve_prepared_planar_contact(contact, b_i[0], b_i[1], r_new[0], r_new[1]) && all_exact;
    } else {
      static_assert(D == 3);
      const PreparedSpatialContact& contact = prepared_spatial[static_cast<std::size_t>(i)];
      local_b(
          i, row_times, r_i, [&](int row, int col) { return contact.a(row, col); }, b_i);
      Eigen::Vector3d r_local = Eigen::Map<const Eigen::Vector3d>(r_new);
      all_exact = solve_prepared_spatial_contact(contact, Eigen::Map<const Eigen::Vector3d>(b_i),
                                                 r_local) &&
                  all_exact;
      for (int row = 0; row < D; ++row) r_new[row] = r_local(row);
    }
  };
  factor_blocks::gauss_seidel_pass<D>(problem.factor_blocks, rigid, problem.num_contacts(),
                                      r.data(), w.data(), solve_locally);
  return all_exact;
}

// The local problems of a factored problem's contacts prepared for the blocked sweeps, planar or
// spatial (D), each from its W_ii formed through the blocks' descriptions (the sums of
// diagonal_blocks, to the bit) without keeping W_ii apart: the sweeps read it from the prepared
// record. A spatial contact's stick case then applies Cramer's rule without forming the
// cofactors again. False, with nothing prepared past it, at a W_nn that is not positive.
template <int D>
bool prepare_blocked_contacts(const FrictionProblem& problem,
                              const std::vector<factor_blocks::RigidContactBlocks>& rigid,
                              PreparedContacts& planar, PreparedSpatialContacts& spatial) {
  const auto contacts = static_cast<std::size_t>(problem.num_contacts());
  planar.resize(D == 2 ? contacts : 0);
  spatial.resize(D == 3 ? contacts : 0);
  return factor_blocks::for_each_positive_diagonal<D>(
      problem.factor_blocks, &rigid, [&](int contact, const double(&w_ii)[D * D]) {
        const auto i = static_cast<std::size_t>(contact);
        if constexpr (D == 2)
          planar[i] = prepare_planar_contact(w_ii, problem.mu(contact));
        else
          spatial[i] = prepare_spatial_contact(
              Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(w_ii),
              problem.mu(contact));
      });
}

// What a solve keeps between solves (see solve_nonsmooth_gauss_seidel).
struct NsgsScratch {
  std::vector<LocalMatrix> blocks;
  PreparedContacts prepared;
  PreparedSpatialContacts prepared_spatial;
  std::vector<factor_blocks::RigidContactBlocks> rigid;
  CapacityVector velocity;
};

}  // namespace

bool nonsmooth_gauss_seidel_sweep(const FrictionProblem& problem,
                                  const std::vector<LocalMatrix>& diagonal_blocks,
                                  CapacityVector& r) {
  return formed_gauss_seidel_sweep(problem, diagonal_blocks, nullptr, r);
}

Outcome solve_nonsmooth_gauss_seidel(const FrictionProblem& problem, const SolverOptions& options,
                                     CapacityVector& r, const SolveEntry& entry) {
  // Kept per thread between solves (a time stepper solves one problem a step), lent to one
  // solve at a time.
  const ThreadKeptLease<NsgsScratch> scratch;
  std::vector<LocalMatrix>& blocks = scratch->blocks;
  PreparedContacts& prepared = scratch->prepared;
  PreparedSpatialContacts& prepared_spatial = scratch->prepared_spatial;
  const bool blocked = problem.is_factored && !problem.factor_blocks.empty();
  // The rigid bodies' contacts described once for the sweeps and the checks' products.
  std::vector<factor_blocks::RigidContactBlocks>& rigid = scratch->rigid;
  if (blocked) {
    const bool positive = factor_blocks::with_dimension(problem.dimension, [&](auto d) {
      factor_blocks::describe_rigid_contacts<d>(problem.factor_blocks, rigid);
      return prepare_blocked_contacts<d>(problem, rigid, prepared, prepared_spatial);
    });
    if (!positive) return nonpositive_normal_diagonal();
  } else {
    diagonal_blocks(problem, blocks);
    for (const LocalMatrix& block : blocks) {
      if (!(block(0, 0) > 0.0)) return nonpositive_normal_diagonal();
    }
    // Planar local problems prepared once: the sweeps then multiply where they divided.
    prepared.clear();
    if (problem.dimension == 2)
      for (int i = 0; i < problem.num_contacts(); ++i)
        prepared.push_back(
            prepare_planar_contact(blocks[static_cast<std::size_t>(i)], problem.mu(i)));
  }
  const PreparedContacts* planar = problem.dimension == 2 ? &prepared : nullptr;
  Outcome outcome;
  outcome.velocity.swap(kept_outcome_velocity());
  const std::vector<factor_blocks::RigidContactBlocks>* described = blocked ? &rigid : nullptr;
  CapacityVector& velocity = scratch->velocity;  // A r of a factored problem
  if (problem.is_factored) take_entry_velocity(problem, r, entry, described, velocity);
  // At every way out below but the non-finite one, `velocity` is A r formed afresh at the
  // returned r (the entry's, or the last check's after the last sweep): it goes to the answer,
  // the same bits as write_factored_velocity forms (the described blocks sum alike).
  const auto hand_over = [&] {
    if (entry.answer_factored_velocity != nullptr) *entry.answer_factored_velocity = velocity;
  };
  // The residual costs about a sweep. Gauss–Seidel contracts about linearly, so from the last
  // two residuals e, e' (k sweeps apart) the sweeps still needed are about
  // k log(tol/e') / log(e'/e); the residual is skipped for half of those (never at the last
  // sweep, where it is always evaluated). A problem that converges fast is checked every sweep.
  // The first e is the driver's residual at the entry r, so the first check already predicts.
  constexpr double kMaxSkipped = 64.0;
  double previous_residual = std::isfinite(entry.residual) ? entry.residual : -1.0;
  int last_checked = 0;
  int next_check = 1;
  const double scale = residual_scale(problem);  // the residual's divisor, for every check
  for (outcome.iterations = 1; outcome.iterations <= options.max_iterations; ++outcome.iterations) {
    if (blocked)
      factor_blocks::with_dimension(problem.dimension, [&](auto d) {
        return blocked_gauss_seidel_sweep<d>(problem, prepared, prepared_spatial, rigid, r,
                                             velocity);
      });
    else if (problem.is_factored)
      factored_gauss_seidel_sweep(problem, blocks, planar, r, velocity);
    else
      formed_gauss_seidel_sweep(problem, blocks, planar, r);
    // r moved, and outcome.velocity is stale until the check below; it keeps its storage, for
    // every way out of the loop after a sweep passes that check (the last sweep is always
    // checked) or returns a fresh Outcome.
    if (outcome.iterations < next_check && outcome.iterations < options.max_iterations) continue;
    if (!r.allFinite())
      return {outcome.iterations, SolverStatus::kStalled, "iterate became non-finite"};
    // u at this r, handed to the driver if the solve ends here.
    if (problem.is_factored) {
      write_factored_velocity(problem, r, velocity, described);  // no drift from updates
      write_factored_contact_velocity(problem, velocity, outcome.velocity, described);
    } else {
      write_contact_velocity(problem, r, outcome.velocity);
    }
    const double residual = friction_residual(problem, r, outcome.velocity, scale);
    outcome.residual = residual;  // at this r: every way out below returns with it
    if (const auto stop = options.stop_status(outcome.iterations, residual)) {
      outcome.status = *stop;
      if (*stop == SolverStatus::kStopped) outcome.message = "stopped by the caller";
      hand_over();
      return outcome;
    }
    next_check = outcome.iterations + 1;
    if (previous_residual > 0.0 && residual < previous_residual && options.tolerance > 0.0) {
      const double needed = std::log(options.tolerance / residual) /
                            std::log(residual / previous_residual) *
                            (outcome.iterations - last_checked);
      // At most kMaxSkipped sweeps unchecked, so a caller's time limit is still honoured.
      if (needed > 4.0)
        next_check = outcome.iterations + static_cast<int>(std::min(needed / 2.0, kMaxSkipped));
    }
    previous_residual = residual;
    last_checked = outcome.iterations;
  }
  // The status (kMaxIterations, Outcome's default) says it: no message, so that a solve with a
  // fixed sweep count, stopped here at every step, allocates nothing for it.
  outcome.iterations = options.max_iterations;
  hand_over();
  return outcome;
}

}  // namespace impactbench::solvers::friction_detail
