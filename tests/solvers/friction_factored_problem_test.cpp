// Friction problems with W kept in its factors (W = H A, A = M⁻¹Hᵀ, as the time stepper builds
// them) against the same problems with W formed: the diagonal blocks and u = W r + q agree to
// round-off, Gauss–Seidel on the factors (swept through the velocity A r) converges to the
// formed problem's solution, the other solvers are given W formed, and malformed factors are
// refused with one clear message.
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/factor_blocks_kernels.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/solvers/random_friction_problem.hpp"
#include "tests/support/solvers/same_result.hpp"

namespace impactbench::solvers {
namespace {

RandomFrictionSpec spec(int dimension, std::uint32_t seed) {
  RandomFrictionSpec s;
  s.contacts = 60;
  s.bodies = 80;  // more degrees of freedom than contact rows: W positive definite
  s.dimension = dimension;
  s.seed = seed;
  return s;
}

// A problem kept in its factors, with the factors by contact blocks too (the time stepper's).
FrictionProblem blocked_problem(int dimension, std::uint32_t seed) {
  RandomFrictionSpec s = spec(dimension, seed);
  s.factored = true;
  s.factor_blocks = true;
  return random_friction_problem(s);
}

// The same random problem with sparse factors alone, and with factor blocks as well.
struct SparseAndBlocked {
  FrictionProblem sparse;
  FrictionProblem blocked;
};
SparseAndBlocked sparse_and_blocked(int dimension, std::uint32_t seed) {
  RandomFrictionSpec s = spec(dimension, seed);
  s.factored = true;
  SparseAndBlocked problems;
  problems.sparse = random_friction_problem(s);
  s.factor_blocks = true;
  problems.blocked = random_friction_problem(s);
  return problems;
}

class FactoredProblem : public ::testing::TestWithParam<int> {};

TEST_P(FactoredProblem, AgreesWithTheFormedProblem) {
  RandomFrictionSpec s = spec(GetParam(), 11);
  s.factored = true;
  const FrictionProblem factored = random_friction_problem(s);
  ASSERT_TRUE(factored.is_factored);
  s.factored = false;
  s.sparse = true;
  const FrictionProblem formed = random_friction_problem(s);

  const auto factored_blocks = diagonal_blocks(factored);
  const auto formed_blocks = diagonal_blocks(formed);
  for (std::size_t i = 0; i < formed_blocks.size(); ++i)
    EXPECT_LT((factored_blocks[i] - formed_blocks[i]).norm(), 1e-12 * formed_blocks[i].norm());
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(formed.size(), -1.0, 2.0);
  EXPECT_LT((contact_velocity(factored, r) - contact_velocity(formed, r)).norm(),
            1e-12 * contact_velocity(formed, r).norm());
  EXPECT_LT((Eigen::MatrixXd(formed_delassus(factored).sparse_W) - Eigen::MatrixXd(formed.sparse_W))
                .norm(),
            1e-12 * Eigen::MatrixXd(formed.sparse_W).norm());

  SolverOptions options;
  options.tolerance = 1e-12;
  options.max_iterations = 100000;
  const SolverResult a = solve_friction(factored, "nsgs", options);
  const SolverResult b = solve_friction(formed, "nsgs", options);
  ASSERT_EQ(a.status, SolverStatus::kConverged) << a.message;
  ASSERT_EQ(b.status, SolverStatus::kConverged) << b.message;
  // Both solve the same strictly monotone problem (W positive definite): one solution.
  EXPECT_LT((a.solution - b.solution).norm(), 1e-8 * b.solution.norm());
  EXPECT_LE(friction_residual(formed, a.solution), 1e-11);

  // A solver that needs W's entries is given it formed; prox-gs sweeps the factors as nsgs does.
  for (const char* solver : {"nsn", "prox-gs"}) {
    const SolverResult c = solve_friction(factored, solver, options);
    ASSERT_EQ(c.status, SolverStatus::kConverged) << solver << ": " << c.message;
    EXPECT_LT((c.solution - b.solution).norm(), 1e-8 * b.solution.norm()) << solver;
  }
}

// prox-gs on the factors by contact blocks (swept through w = A r) against prox-gs on the same
// W formed: the same sweeps in exact arithmetic, so after a fixed number of sweeps the iterates
// differ by rounding only, and both converge to the one solution (W positive definite), which
// has a residual below the tolerance on the formed W. With steps far too long (ρ × 50) the
// solve first diverges, goes back to its best iterate (w then follows r) and still converges.
TEST_P(FactoredProblem, ProxGsOnTheBlocksSweepsAsOnTheFormedW) {
  const FrictionProblem blocked = blocked_problem(GetParam(), 16);
  const FrictionProblem formed = formed_delassus(blocked);
  ASSERT_FALSE(formed.is_factored);
  for (const double rho_scale : {1.0, 50.0}) {
    SolverOptions options;
    options.rho_scale = rho_scale;
    options.tolerance = 1e-12;
    options.max_iterations = 7;
    const SolverResult a7 = solve_friction(blocked, "prox-gs", options);
    const SolverResult b7 = solve_friction(formed, "prox-gs", options);
    ASSERT_EQ(a7.solution.size(), b7.solution.size());
    // Seven sweeps of a contraction: rounding (1e-16 relative per operation) is not amplified
    // beyond the problem's conditioning; 1e-10 leaves six orders of magnitude for it.
    EXPECT_LE((a7.solution - b7.solution).norm(), 1e-10 * b7.solution.norm()) << rho_scale;
    EXPECT_LE(std::abs(a7.residual - b7.residual), 1e-10 * b7.residual) << rho_scale;
    options.max_iterations = 100000;
    const SolverResult a = solve_friction(blocked, "prox-gs", options);
    const SolverResult b = solve_friction(formed, "prox-gs", options);
    ASSERT_EQ(a.status, SolverStatus::kConverged) << rho_scale << ": " << a.message;
    ASSERT_EQ(b.status, SolverStatus::kConverged) << rho_scale << ": " << b.message;
    EXPECT_LT((a.solution - b.solution).norm(), 1e-8 * b.solution.norm()) << rho_scale;
    // The tolerance, with the rounding of the other form of W in u.
    EXPECT_LE(friction_residual(formed, a.solution), 2e-12) << rho_scale;
    // The reported figures are those of the returned r.
    EXPECT_EQ(a.residual, friction_residual(blocked, a.solution)) << rho_scale;
  }
}

// The driver reports u and the residual at the returned r from the solver's last evaluation
// (nsgs evaluates it at its last sweep): they must be those of a fresh product with W, whether
// the solve converges, stops at the iteration limit or starts from a solution.
// With factor blocks as well, whose products are summed by the blocks' own kernels.
TEST_P(FactoredProblem, ReportedVelocityAndResidualAreThoseOfTheSolution) {
  for (const bool blocks : {false, true}) {
    RandomFrictionSpec s = spec(GetParam(), 12);
    s.factored = true;
    s.factor_blocks = blocks;
    const FrictionProblem problem = random_friction_problem(s);
    ASSERT_EQ(problem.factor_blocks.empty(), !blocks);
    SolverOptions options;
    options.tolerance = 1e-10;
    for (const int max_iterations : {1, 3, 100000}) {
      options.max_iterations = max_iterations;
      const SolverResult result = solve_friction(problem, "nsgs", options);
      ASSERT_EQ(result.velocity.size(), problem.size());
      EXPECT_EQ(result.velocity, contact_velocity(problem, result.solution))
          << max_iterations << " " << blocks;
      EXPECT_EQ(result.residual, friction_residual(problem, result.solution))
          << max_iterations << " " << blocks;
    }
    const SolverResult solved = solve_friction(problem, "nsgs", options);
    ASSERT_EQ(solved.status, SolverStatus::kConverged) << solved.message;
    EXPECT_GT(solved.iterations, 10) << blocks;  // a solve of many sweeps
    const SolverResult again = solve_friction(problem, "nsgs", options, &solved.solution);
    EXPECT_EQ(again.iterations, 0);
    EXPECT_EQ(again.velocity, contact_velocity(problem, solved.solution));
  }
}

// nsgs and prox-gs hand over A r at their answer (a time stepper's M⁻¹Jᵀ r), to the bit of
// write_factored_velocity there: after any number of sweeps, with sparse factors and with
// blocks, and for an answer found at the entry. nsgs forms it at its last check, prox-gs's comes
// from the driver's u after the solve. A result solved into again for a formed problem keeps no
// stale one, and a formed problem has none.
TEST_P(FactoredProblem, SweepsHandOverTheVelocityAtTheirAnswer) {
  const auto [sparse, blocked] = sparse_and_blocked(GetParam(), 21);
  SolverOptions options;
  options.tolerance = 1e-10;
  for (const FrictionProblem* problem : {&sparse, &blocked}) {
    const auto at = [&](const CapacityVector& r) {
      CapacityVector velocity;
      write_factored_velocity(*problem, r, velocity);
      return velocity;
    };
    for (const char* solver : {"nsgs", "prox-gs"}) {
      for (const int max_iterations : {0, 1, 3, 100000}) {
        options.max_iterations = max_iterations;
        const SolverResult result = solve_friction(*problem, solver, options);
        ASSERT_EQ(result.factored_velocity.size(), problem->factored_velocities())
            << solver << " " << max_iterations;
        EXPECT_TRUE(same_bits(result.factored_velocity, at(result.solution)))
            << solver << " " << max_iterations;
      }
      const SolverResult solved = solve_friction(*problem, solver, options);
      ASSERT_EQ(solved.status, SolverStatus::kConverged) << solver << " " << solved.message;
      const SolverResult again = solve_friction(*problem, solver, options, &solved.solution);
      ASSERT_EQ(again.iterations, 0) << solver;
      EXPECT_TRUE(same_bits(again.factored_velocity, at(solved.solution))) << solver;
    }

    SolverResult kept;
    options.max_iterations = 3;
    FrictionSolver("prox-gs").solve(*problem, options, nullptr, kept);
    ASSERT_GT(kept.iterations, 0);  // not an answer at the entry
    ASSERT_GT(kept.factored_velocity.size(), 0);
    FrictionSolver("nsgs").solve(formed_delassus(*problem), options, nullptr, kept);
    ASSERT_GT(kept.iterations, 0);
    EXPECT_EQ(kept.factored_velocity.size(), 0);
  }
}

// Moving a problem hands over its factors (Eigen 3.4's sparse matrices are swapped, not copied).
TEST_P(FactoredProblem, MovingKeepsEveryPart) {
  const FrictionProblem original = blocked_problem(GetParam(), 13);
  FrictionProblem source = original;
  const FrictionProblem moved(std::move(source));
  FrictionProblem assigned;
  assigned = FrictionProblem(moved);
  const auto expect_original = [&](const FrictionProblem& p) {
    EXPECT_TRUE(p.is_factored);
    EXPECT_EQ(p.dimension, original.dimension);
    EXPECT_EQ(Eigen::MatrixXd(p.factor_H), Eigen::MatrixXd(original.factor_H));
    EXPECT_EQ(Eigen::MatrixXd(p.factor_A), Eigen::MatrixXd(original.factor_A));
    EXPECT_EQ(p.q, original.q);
    EXPECT_EQ(p.mu, original.mu);
    EXPECT_EQ(p.factor_blocks.values, original.factor_blocks.values);
    EXPECT_EQ(p.factor_blocks.contact_start, original.factor_blocks.contact_start);
  };
  expect_original(moved);
  expect_original(assigned);
}

// u = W r + q and nsgs's answers of `blocked` equal those of `sparse` to the bit, stopped at an
// iteration limit and converged.
void expect_same_velocity_and_nsgs_answers(const FrictionProblem& blocked,
                                           const FrictionProblem& sparse) {
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(sparse.size(), -1.0, 2.0);
  EXPECT_EQ(contact_velocity(blocked, r), contact_velocity(sparse, r));
  // Contacts without impulse (of either zero's sign), beside ones with a zero component only.
  Eigen::VectorXd with_zeros = r;
  const int d = sparse.dimension;
  for (int i = 0; i < sparse.num_contacts(); i += 3) {
    with_zeros.segment(i * d, d).setConstant(i % 2 == 0 ? 0.0 : -0.0);
    if (i + 1 < sparse.num_contacts()) with_zeros((i + 1) * d) = 0.0;
  }
  EXPECT_EQ(factored_velocity(blocked, with_zeros), factored_velocity(sparse, with_zeros));
  EXPECT_EQ(contact_velocity(blocked, with_zeros), contact_velocity(sparse, with_zeros));
  SolverOptions options;
  options.tolerance = 1e-12;
  for (const int max_iterations : {7, 100000}) {
    options.max_iterations = max_iterations;
    const SolverResult a = solve_friction(blocked, "nsgs", options);
    const SolverResult b = solve_friction(sparse, "nsgs", options);
    EXPECT_EQ(a.status, b.status) << max_iterations << ": " << a.message;
    EXPECT_EQ(a.iterations, b.iterations) << max_iterations;
    EXPECT_EQ(a.solution, b.solution) << max_iterations;
    EXPECT_EQ(a.residual, b.residual) << max_iterations;
  }
  EXPECT_EQ(solve_friction(blocked, "nsgs", options).status, SolverStatus::kConverged);
}

// The factors by contact blocks (FactorBlocks) give the sparse factors' products and sweeps to the
// bit: they sum the same products in the same order (factor_blocks_kernels.hpp), converged or
// stopped at an iteration limit, and so do the diagonal blocks and u = W r + q.
TEST_P(FactoredProblem, BlocksGiveTheSparseFactorsAnswerToTheBit) {
  const auto [sparse, blocked] = sparse_and_blocked(GetParam(), 14);
  ASSERT_TRUE(sparse.factor_blocks.empty());
  ASSERT_EQ(blocked.factor_blocks.contact_start.size(),
            static_cast<std::size_t>(blocked.num_contacts()) + 1);

  const auto sparse_blocks = diagonal_blocks(sparse);
  const auto blocked_blocks = diagonal_blocks(blocked);
  for (std::size_t i = 0; i < sparse_blocks.size(); ++i)
    EXPECT_EQ(blocked_blocks[i], sparse_blocks[i]) << i;
  expect_same_velocity_and_nsgs_answers(blocked, sparse);
}

// A problem given by its factor blocks alone (factor_H and factor_A empty, as the time stepper's
// assembly gives it) is the same problem: the sweeping solvers give its answer to the bit, the
// products of delassus_access give the same vectors, and a solver that needs W forms it from the
// blocks.
TEST_P(FactoredProblem, ByItsBlocksAloneIsTheSameProblem) {
  const FrictionProblem with_factors = blocked_problem(GetParam(), 16);
  FrictionProblem alone = with_factors;
  alone.factor_H = Eigen::SparseMatrix<double, Eigen::RowMajor>();
  alone.factor_A = Eigen::SparseMatrix<double>();
  ASSERT_TRUE(alone.factored_by_blocks_only());
  ASSERT_FALSE(with_factors.factored_by_blocks_only());
  EXPECT_EQ(alone.factored_velocities(), with_factors.factor_A.rows());

  for (const char* solver : {"nsgs", "prox-gs"}) {
    SCOPED_TRACE(solver);
    const SolverResult by_blocks = solve_friction(alone, solver);
    EXPECT_TRUE(by_blocks.converged()) << by_blocks.message;
    expect_same_result(by_blocks, solve_friction(with_factors, solver));
  }
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(alone.size(), -1.0, 2.0);
  EXPECT_EQ(factored_velocity(alone, r), factored_velocity(with_factors, r));
  EXPECT_EQ(contact_velocity(alone, r), contact_velocity(with_factors, r));
  for (const int contact : {0, 7, alone.num_contacts() - 1})
    EXPECT_EQ(block_row_times(alone, contact, r), block_row_times(with_factors, contact, r))
        << contact;
  const Eigen::MatrixXd W = Eigen::MatrixXd(formed_delassus(with_factors).sparse_W);
  EXPECT_LT((Eigen::MatrixXd(formed_delassus(alone).sparse_W) - W).norm(), 1e-14 * W.norm());
  const SolverResult newton = solve_friction(alone, "nsn");
  EXPECT_TRUE(newton.converged()) << newton.message;
  EXPECT_LT((newton.solution - solve_friction(with_factors, "nsn").solution).norm(),
            1e-8 * newton.solution.norm());
}

// The same factors with each block of the even contacts split into a range of one velocity and
// one of the rest: blocks of no rigid body, which the sweep reads through the general kernels
// while the odd contacts keep their rigid bodies' blocks.
FactorBlocks split_even_contacts(const FactorBlocks& blocks, int d) {
  FactorBlocks out;
  out.velocities = blocks.velocities;
  out.contact_start.push_back(0);
  const auto contacts = blocks.contact_start.size() - 1;
  for (std::size_t i = 0; i < contacts; ++i) {
    for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
      const auto k = static_cast<std::size_t>(b);
      const int size = blocks.size[k];
      const double* h = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
      const double* a = h + size * d;
      const auto add = [&](int from, int count) {
        out.first_velocity.push_back(blocks.first_velocity[k] + from);
        out.size.push_back(count);
        out.offset.push_back(static_cast<int>(out.values.size()));
        out.values.insert(out.values.end(), h + from * d, h + (from + count) * d);
        for (int component = 0; component < d; ++component)
          out.values.insert(out.values.end(), a + component * size + from,
                            a + component * size + from + count);
      };
      if (i % 2 == 0) {
        add(0, 1);
        add(1, size - 1);
      } else {
        add(0, size);
      }
    }
    out.contact_start.push_back(static_cast<int>(out.first_velocity.size()));
  }
  return out;
}

TEST_P(FactoredProblem, BlocksOfAnySizeGiveTheSparseFactorsAnswerToTheBit) {
  auto [sparse, split] = sparse_and_blocked(GetParam(), 15);
  split.factor_blocks = split_even_contacts(split.factor_blocks, split.dimension);
  ASSERT_GT(split.factor_blocks.size.size(),
            3u * static_cast<std::size_t>(split.num_contacts()) / 2);

  expect_same_velocity_and_nsgs_answers(split, sparse);
}

// H w and H x in one pass over the blocks (the stepper's J v_free and J v_k) are the sparse
// factor's products to the bit, with blocks of rigid bodies and with split ones.
TEST_P(FactoredProblem, PairedRowProductsAreTheSparseFactorsProducts) {
  const auto [sparse, rigid_blocks] = sparse_and_blocked(GetParam(), 19);
  FrictionProblem split = rigid_blocks;
  split.factor_blocks = split_even_contacts(split.factor_blocks, split.dimension);
  const auto nv = sparse.factor_H.cols();
  const Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(nv, -1.0, 2.0);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(nv, 3.0, -0.5).cwiseProduct(w);
  const Eigen::VectorXd h_w = sparse.factor_H * w;
  const Eigen::VectorXd h_x = sparse.factor_H * x;
  ASSERT_GT(h_w.cwiseAbs().minCoeff(), 0.0);  // every row sums terms that do not all vanish
  for (const FrictionProblem* problem :
       {&rigid_blocks, static_cast<const FrictionProblem*>(&split)}) {
    CapacityVector out_w, out_x;
    write_factor_rows_times(problem->factor_blocks, problem->dimension, w, out_w, x, out_x);
    EXPECT_TRUE(same_bits(out_w, h_w));
    EXPECT_TRUE(same_bits(out_x, h_x));
  }
}

// The residual from w = A r that forms u = H w + q contact by contact (prox-gs's check) is the
// residual of the stored u to the bit: through the rigid bodies' descriptions or without them,
// and with blocks of no rigid body, at impulses inside, on and outside the cone.
TEST_P(FactoredProblem, ResidualFromTheVelocityIsThatOfTheStoredContactVelocity) {
  const FrictionProblem rigid_blocks = blocked_problem(GetParam(), 17);
  FrictionProblem split = rigid_blocks;
  split.factor_blocks = split_even_contacts(split.factor_blocks, split.dimension);
  for (const FrictionProblem* problem :
       {&rigid_blocks, static_cast<const FrictionProblem*>(&split)}) {
    std::vector<factor_blocks::RigidContactBlocks> rigid;
    factor_blocks::with_dimension(problem->dimension, [&](auto d) {
      factor_blocks::describe_rigid_contacts<d>(problem->factor_blocks, rigid);
    });
    for (const Eigen::VectorXd& r :
         {Eigen::VectorXd(Eigen::VectorXd::LinSpaced(problem->size(), -1.0, 2.0)),
          Eigen::VectorXd(Eigen::VectorXd::Zero(problem->size())),
          Eigen::VectorXd(solve_friction(*problem, "nsgs").solution)}) {
      CapacityVector w;
      write_factored_velocity(*problem, r, w, &rigid);
      const double expected = friction_residual(*problem, r);
      EXPECT_GT(expected, 0.0);  // terms that do not all vanish
      EXPECT_EQ(factored_friction_residual(*problem, r, w, &rigid), expected);
      EXPECT_EQ(factored_friction_residual(*problem, r, w, nullptr), expected);
      EXPECT_EQ(factored_friction_residual(*problem, r, w, &rigid, residual_scale(*problem)),
                expected);
    }
  }
}

// prox-gs takes its residual after a sweep at the velocity the sweep carried along, and confirms
// one that meets the tolerance at A r formed afresh. With the tolerance set to a sweep's residual
// as prox-gs saw it (a new lowest one, so that no earlier sweep meets it and the solve runs as
// before up to that sweep), the solve stops at that sweep only where the fresh residual meets
// the tolerance too, and goes on where rounding put the fresh one above it: it never reports
// a convergence that the residual of the returned r denies.
TEST_P(FactoredProblem, ProxGsConfirmsAResidualThatMeetsTheToleranceAfresh) {
  const FrictionProblem problem = blocked_problem(GetParam(), 18);
  SolverOptions recording;
  recording.tolerance = 0.0;
  recording.max_iterations = 80;
  std::vector<std::pair<int, double>> seen;  // (sweep, residual) as prox-gs saw them
  recording.monitor = [&](int sweep, double residual) {
    seen.emplace_back(sweep, residual);
    return true;
  };
  solve_friction(problem, "prox-gs", recording);
  ASSERT_GT(seen.size(), 40u);

  double lowest =
      friction_residual(problem, Eigen::VectorXd(Eigen::VectorXd::Zero(problem.size())));  // entry
  int stopped_there = 0, went_on = 0;
  for (const auto& [sweep, residual] : seen) {
    if (!(residual < lowest)) continue;
    lowest = residual;
    SolverOptions options;
    options.tolerance = residual;
    options.max_iterations = 100000;
    const SolverResult result = solve_friction(problem, "prox-gs", options);
    // The driver's word when a solver claims a convergence that the returned r does not have.
    EXPECT_EQ(result.message.find("above tolerance"), std::string::npos)
        << sweep << ": " << result.message;
    EXPECT_GE(result.iterations, sweep);
    if (result.iterations == sweep) {
      EXPECT_EQ(result.status, SolverStatus::kConverged) << sweep << ": " << result.message;
      EXPECT_LE(result.residual, residual) << sweep;
      ++stopped_there;
    } else {
      ++went_on;  // on to convergence, or to a stall of ω further on
    }
  }
  // Both outcomes occur: the confirmation decided, not the swept residual alone.
  EXPECT_GT(stopped_there, 0);
  EXPECT_GT(went_on, 0);
}

// nsgs and prox-gs form each W_ii of a problem with factor blocks from the blocks themselves: a
// contact whose normal row of H and column of A are zero (W_nn = 0) is refused as singular, as
// on a formed W, while the same problem with that contact intact is solved; and a diagonal entry
// of W found through the blocks equals the formed W's.
TEST_P(FactoredProblem, BlockedSolversRefuseAZeroNormalDiagonalOfTheBlocks) {
  const int d = GetParam();
  const FrictionProblem intact = blocked_problem(d, 21);
  const Eigen::MatrixXd W = Eigen::MatrixXd(formed_delassus(intact).sparse_W);
  for (const char* solver : {"nsgs", "prox-gs"}) {
    SCOPED_TRACE(solver);
    const SolverResult solved = solve_friction(intact, solver);
    EXPECT_TRUE(solved.converged()) << solved.message;
    for (const int contact : {0, 17, intact.num_contacts() - 1}) {
      SCOPED_TRACE(contact);
      EXPECT_EQ(diagonal_block(intact, contact)(0, 0), W(contact * d, contact * d));
      FrictionProblem singular = intact;
      FactorBlocks& blocks = singular.factor_blocks;
      const auto i = static_cast<std::size_t>(contact);
      for (int b = blocks.contact_start[i]; b < blocks.contact_start[i + 1]; ++b) {
        const auto k = static_cast<std::size_t>(b);
        const int size = blocks.size[k];
        double* h = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
        double* a = h + static_cast<std::ptrdiff_t>(size) * d;
        for (int s = 0; s < size; ++s) h[s * d] = a[s] = 0.0;  // H's row 0, A's column 0
      }
      singular.factor_H = Eigen::SparseMatrix<double, Eigen::RowMajor>();  // the blocks alone
      singular.factor_A = Eigen::SparseMatrix<double>();
      ASSERT_EQ(diagonal_block(singular, contact)(0, 0), 0.0);
      const SolverResult refused = solve_friction(singular, solver);
      EXPECT_EQ(refused.status, SolverStatus::kSingular) << refused.message;
      EXPECT_NE(refused.message.find("W_nn"), std::string::npos) << refused.message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PlanarAndSpatial, FactoredProblem, ::testing::Values(2, 3));

TEST(FactoredProblemInput, MalformedFactorsAreRefused) {
  RandomFrictionSpec s = spec(2, 3);
  s.factored = true;
  SolverOptions options;

  FrictionProblem wrong_size = random_friction_problem(s);
  wrong_size.factor_A.conservativeResize(wrong_size.factor_A.rows(),
                                         wrong_size.factor_A.cols() - 1);
  const SolverResult sized = solve_friction(wrong_size, "nsgs", options);
  EXPECT_EQ(sized.status, SolverStatus::kInvalidProblem);
  EXPECT_NE(sized.message.find("factors of W"), std::string::npos) << sized.message;

  s.factor_blocks = true;
  const auto refused = [&](FrictionProblem problem, SolverStatus status, const char* words) {
    const SolverResult result = solve_friction(problem, "nsgs", options);
    EXPECT_EQ(result.status, status) << result.message;
    EXPECT_NE(result.message.find(words), std::string::npos) << result.message;
  };
  FrictionProblem missing_contact = random_friction_problem(s);
  missing_contact.factor_blocks.contact_start.pop_back();
  refused(missing_contact, SolverStatus::kInvalidProblem, "does not list 60 contacts");
  FrictionProblem outside = random_friction_problem(s);
  outside.factor_blocks.first_velocity.back() = static_cast<int>(outside.factor_A.rows()) - 1;
  refused(outside, SolverStatus::kInvalidProblem, "lies outside the velocities");
  FrictionProblem overlapping = random_friction_problem(s);
  overlapping.factor_blocks.first_velocity[1] = overlapping.factor_blocks.first_velocity[0];
  refused(overlapping, SolverStatus::kInvalidProblem, "overlaps the one before");
  FrictionProblem miscounted = random_friction_problem(s);
  miscounted.factor_blocks.velocities -= 1;
  refused(miscounted, SolverStatus::kInvalidProblem, "velocities, A has");
  FrictionProblem alone_too_few = random_friction_problem(s);
  alone_too_few.factor_H = Eigen::SparseMatrix<double, Eigen::RowMajor>();
  alone_too_few.factor_A = Eigen::SparseMatrix<double>();
  alone_too_few.factor_blocks.velocities = alone_too_few.factor_blocks.first_velocity.back();
  refused(alone_too_few, SolverStatus::kInvalidProblem, "lies outside the velocities");
  FrictionProblem nan_block = random_friction_problem(s);
  nan_block.factor_blocks.values[5] = std::numeric_limits<double>::quiet_NaN();
  refused(nan_block, SolverStatus::kNonFiniteData, "NaN");
  s.factor_blocks = false;

  FrictionProblem not_finite = random_friction_problem(s);
  not_finite.factor_H.valuePtr()[3] = std::numeric_limits<double>::quiet_NaN();
  const SolverResult nan = solve_friction(not_finite, "nsgs", options);
  EXPECT_EQ(nan.status, SolverStatus::kNonFiniteData);
  EXPECT_NE(nan.message.find("NaN"), std::string::npos) << nan.message;
}

}  // namespace
}  // namespace impactbench::solvers
