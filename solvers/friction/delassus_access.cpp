#include "solvers/friction/delassus_access.hpp"

#include <algorithm>

#include "solvers/friction/factor_blocks_kernels.hpp"

namespace impactbench::solvers {

// With factor_blocks, each product below sums in the order of the sparse factors' own product
// (factor_blocks_kernels.hpp): the same vectors to the bit, from contiguous blocks.

CapacityVector factored_velocity(const FrictionProblem& problem, VectorView r) {
  CapacityVector velocity;
  write_factored_velocity(problem, r, velocity);
  return velocity;
}

void write_factored_velocity(const FrictionProblem& problem, VectorView r, CapacityVector& out,
                             const std::vector<factor_blocks::RigidContactBlocks>* rigid) {
  // The product into zeros, then summed: what Eigen does for a product it returns.
  if (problem.factor_blocks.empty()) {
    out.assign_noalias(problem.factor_A * r);
    return;
  }
  out.setZero(problem.factored_velocities());
  factor_blocks::with_dimension(problem.dimension, [&](auto d) {
    for (int i = 0; i < problem.num_contacts(); ++i) {
      const double* r_i = r.data() + static_cast<std::ptrdiff_t>(i) * d;
      // A contact without impulse (an open one) would add products ±0, which leave every sum as
      // it is (a sum from +0 is never −0, and x + ±0 = x otherwise; the blocks are finite): the
      // same bits without reading its blocks.
      if (factor_blocks::is_zero<d>(r_i)) continue;
      factor_blocks::add_columns<d>(problem.factor_blocks, rigid, i, r_i, out.data());
    }
  });
}

CapacityVector factored_contact_velocity(const FrictionProblem& problem, VectorView velocity) {
  CapacityVector u;
  write_factored_contact_velocity(problem, velocity, u);
  return u;
}

void write_factored_contact_velocity(const FrictionProblem& problem, VectorView velocity,
                                     CapacityVector& out,
                                     const std::vector<factor_blocks::RigidContactBlocks>* rigid) {
  if (problem.factor_blocks.empty()) {
    // H w + q as Eigen forms it: H w into zeros, then q added.
    out.assign_noalias(problem.factor_H * velocity);
    out += problem.q;
    return;
  }
  write_factor_rows_times(problem.factor_blocks, problem.dimension, velocity, out, rigid);
  out += problem.q;
}

void write_factor_rows_times(const FactorBlocks& blocks, int dimension, VectorView velocity,
                             CapacityVector& out,
                             const std::vector<factor_blocks::RigidContactBlocks>* rigid) {
  const int contacts = blocks.contacts();
  out.resize(static_cast<Eigen::Index>(contacts) * dimension);
  // Each contact's rows summed from zero where they are at hand, then stored: the sums of a
  // product into zeros, without a pass that zeroes `out` first.
  factor_blocks::with_dimension(dimension, [&](auto d) {
    for (int i = 0; i < contacts; ++i) {
      double rows[d] = {};
      factor_blocks::add_rows<d>(blocks, rigid, i, velocity.data(), rows);
      std::copy_n(rows, d, out.data() + static_cast<std::ptrdiff_t>(i) * d);
    }
  });
}

void write_factor_rows_times(const FactorBlocks& blocks, int dimension, VectorView w,
                             CapacityVector& out_w, VectorView x, CapacityVector& out_x) {
  const int contacts = blocks.contacts();
  out_w.resize(static_cast<Eigen::Index>(contacts) * dimension);
  out_x.resize(static_cast<Eigen::Index>(contacts) * dimension);
  factor_blocks::with_dimension(dimension, [&](auto d) {
    for (int i = 0; i < contacts; ++i) {
      // The contact's blocks are read from memory once and from the first-level cache again;
      // its rows summed from zero as above.
      double rows_w[d] = {}, rows_x[d] = {};
      factor_blocks::add_contact_rows<d>(blocks, i, w.data(), rows_w);
      factor_blocks::add_contact_rows<d>(blocks, i, x.data(), rows_x);
      const auto row = static_cast<std::ptrdiff_t>(i) * d;
      std::copy_n(rows_w, d, out_w.data() + row);
      std::copy_n(rows_x, d, out_x.data() + row);
    }
  });
}

CapacityVector contact_velocity(const FrictionProblem& problem, VectorView r) {
  CapacityVector u;
  write_contact_velocity(problem, r, u);
  return u;
}

void write_contact_velocity(const FrictionProblem& problem, VectorView r, CapacityVector& out,
                            CapacityVector* factored_velocity) {
  if (problem.is_factored) {
    // A r in storage kept per thread unless the caller keeps it: a time stepper's driver and
    // solver ask for u at every solve.
    thread_local CapacityVector kept;
    CapacityVector& velocity = factored_velocity != nullptr ? *factored_velocity : kept;
    write_factored_velocity(problem, r, velocity);
    write_factored_contact_velocity(problem, velocity, out);
    return;
  }
  // W r into zeros, then q added: what Eigen does for W r + q returned.
  if (problem.is_sparse)
    out.assign_noalias(problem.sparse_W * r);
  else
    out.assign_noalias(problem.dense_W * r);
  out += problem.q;
}

LocalVector block_row_times(const FrictionProblem& problem, int contact, VectorView r) {
  const int d = problem.dimension;
  LocalVector result(d);
  if (problem.is_factored) {  // a whole A r: only for solvers that sweep it rarely
    const CapacityVector velocity = factored_velocity(problem, r);
    if (!problem.factor_blocks.empty()) {
      double rows[3] = {};
      factor_blocks::with_dimension(d, [&](auto dim) {
        factor_blocks::add_rows<dim>(problem.factor_blocks, nullptr, contact, velocity.data(),
                                     rows);
      });
      for (int k = 0; k < d; ++k) result(k) = rows[k];
      return result;
    }
    for (int k = 0; k < d; ++k) result(k) = problem.factor_H.row(contact * d + k).dot(velocity);
    return result;
  }
  if (!problem.is_sparse) {
    result.noalias() = problem.dense_W.middleRows(contact * d, d) * r;
    return result;
  }
  for (int k = 0; k < d; ++k) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_W,
                                                                        contact * d + k);
         it; ++it) {
      sum += it.value() * r(it.col());
    }
    result(k) = sum;
  }
  return result;
}

namespace {

// W_ii = Σ_b J_ib H_ib of a problem with factor blocks, into `block` (D × D).
template <int D>
void write_blocked_diagonal_block(const FrictionProblem& problem, int contact, LocalMatrix& block) {
  double sums[D][D] = {};
  factor_blocks::add_contact_diagonal_block<D>(problem.factor_blocks, contact, &sums[0][0]);
  block.resize(D, D);
  for (int row = 0; row < D; ++row)
    for (int col = 0; col < D; ++col) block(row, col) = sums[row][col];
}

}  // namespace

LocalMatrix diagonal_block(const FrictionProblem& problem, int contact) {
  const int d = problem.dimension;
  const int first = contact * d;
  if (problem.is_factored && !problem.factor_blocks.empty()) {  // W_ii = Σ_b J_ib H_ib
    LocalMatrix block;
    factor_blocks::with_dimension(
        d, [&](auto dim) { write_blocked_diagonal_block<dim>(problem, contact, block); });
    return block;
  }
  if (problem.is_factored) {  // W_ii = H_i A_i: sparse rows of H times sparse columns of A
    LocalMatrix block(d, d);
    for (int k = 0; k < d; ++k)
      for (int c = 0; c < d; ++c)
        block(k, c) = problem.factor_H.row(first + k).dot(problem.factor_A.col(first + c));
    return block;
  }
  if (!problem.is_sparse) return problem.dense_W.block(first, first, d, d);
  LocalMatrix block = LocalMatrix::Zero(d, d);
  for (int k = 0; k < d; ++k) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(problem.sparse_W,
                                                                        first + k);
         it; ++it) {
      const auto col = it.col();
      if (col >= first && col < first + d) block(k, col - first) += it.value();
    }
  }
  return block;
}

std::vector<LocalMatrix> diagonal_blocks(const FrictionProblem& problem) {
  std::vector<LocalMatrix> blocks;
  diagonal_blocks(problem, blocks);
  return blocks;
}

void diagonal_blocks(const FrictionProblem& problem, std::vector<LocalMatrix>& blocks) {
  if (problem.is_factored && !problem.factor_blocks.empty()) {
    // Written in place, with one dispatch on the dimension for all contacts.
    blocks.resize(static_cast<std::size_t>(problem.num_contacts()));
    factor_blocks::with_dimension(problem.dimension, [&](auto dim) {
      for (int i = 0; i < problem.num_contacts(); ++i)
        write_blocked_diagonal_block<dim>(problem, i, blocks[static_cast<std::size_t>(i)]);
    });
    return;
  }
  blocks.clear();  // kept storage grows geometrically with push_back
  for (int i = 0; i < problem.num_contacts(); ++i) blocks.push_back(diagonal_block(problem, i));
}

void sparse_factors_from_blocks(const FactorBlocks& blocks, int dimension,
                                Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                                Eigen::SparseMatrix<double>& A) {
  const int contacts = blocks.contacts();
  std::vector<Eigen::Triplet<double>> h_entries, a_entries;
  for (int i = 0; i < contacts; ++i) {
    const auto contact = static_cast<std::size_t>(i);
    for (int b = blocks.contact_start[contact]; b < blocks.contact_start[contact + 1]; ++b) {
      const auto k = static_cast<std::size_t>(b);
      const int first = blocks.first_velocity[k], size = blocks.size[k];
      const double* h = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
      const double* a = h + static_cast<std::ptrdiff_t>(size) * dimension;
      for (int col = 0; col < size; ++col)
        for (int row = 0; row < dimension; ++row) {
          const int contact_row = i * dimension + row;
          // H without its zeros, as the assembly of J leaves them out; A with all its entries.
          if (const double value = h[col * dimension + row]; value != 0.0)
            h_entries.emplace_back(contact_row, first + col, value);
          a_entries.emplace_back(first + col, contact_row, a[row * size + col]);
        }
    }
  }
  H.resize(contacts * dimension, blocks.velocities);
  H.setFromTriplets(h_entries.begin(), h_entries.end());
  A.resize(blocks.velocities, contacts * dimension);
  A.setFromTriplets(a_entries.begin(), a_entries.end());
}

FrictionProblem formed_delassus(const FrictionProblem& problem) {
  if (!problem.is_factored) return problem;
  const auto formed = [&](const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                          const Eigen::SparseMatrix<double>& A) {
    Eigen::SparseMatrix<double, Eigen::RowMajor> W = H * A;
    W.makeCompressed();
    return FrictionProblem::sparse(problem.dimension, std::move(W), problem.q.eval(),
                                   problem.mu.eval());
  };
  if (!problem.factored_by_blocks_only()) return formed(problem.factor_H, problem.factor_A);
  // The sparse factors from the blocks, without a copy of the problem to hold them.
  Eigen::SparseMatrix<double, Eigen::RowMajor> H;
  Eigen::SparseMatrix<double> A;
  sparse_factors_from_blocks(problem.factor_blocks, problem.dimension, H, A);
  return formed(H, A);
}

}  // namespace impactbench::solvers
