// The Moreau–Jean stepper's contract: option validation, misuse errors, non-convergence as a
// value (stop or warn), the block-diagonal M⁻¹ and the Delassus assembly against dense
// formulas, warm starts, the energy and penetration bookkeeping of the run summary.
#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"
#include "lib/engines/moreau_jean/block_sparse_delassus.hpp"
#include "lib/engines/moreau_jean/delassus_assembly.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tests/support/lib/double_bits.hpp"
#include "tests/support/lib/error_message.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using test_support::PlanarTestBody;
using test_support::PlanarTestWorld;

PlanarTestWorld box_on_ground(double friction = 0.5, double restitution = 0.0) {
  return PlanarTestWorld({{"box", 1.0, 0.0, 0.2, 0.2}}, 9.81, friction, restitution);
}

template <typename F>
std::string error_of(F&& f) {
  return test_support::error_message_of<std::invalid_argument>(std::forward<F>(f));
}

TEST(MoreauStepperApi, RejectsInvalidOptionsNamingTheField) {
  const auto world = box_on_ground();
  const auto make = [&](MoreauJeanOptions o) { MoreauJeanStepper s(world, o); };
  MoreauJeanOptions o;
  o.dt = 0.0;
  EXPECT_NE(error_of([&] { make(o); }).find("dt"), std::string::npos);
  o = {};
  o.theta = 0.4;
  EXPECT_NE(error_of([&] { make(o); }).find("theta"), std::string::npos);
  o = {};
  o.solver = "no-such-solver";
  EXPECT_NE(error_of([&] { make(o); }).find("no-such-solver"), std::string::npos);
  o = {};
  o.cone_facets = 2;
  EXPECT_NE(error_of([&] { make(o); }).find("cone_facets"), std::string::npos);
  o = {};
  o.tolerance = std::nan("");
  EXPECT_NE(error_of([&] { make(o); }).find("tolerance"), std::string::npos);
}

TEST(MoreauStepperApi, RejectsBadStateInputAndContactData) {
  auto world = box_on_ground();
  MoreauJeanStepper stepper(world, {});
  EXPECT_NE(error_of([&] {
              stepper.simulate(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(3), {}, 1);
            }).find("q has size"),
            std::string::npos);
  Eigen::VectorXd q(3);
  q << 0, 0.1, std::nan("");
  EXPECT_NE(
      error_of([&] { stepper.simulate(q, Eigen::VectorXd::Zero(3), {}, 1); }).find("not finite"),
      std::string::npos);

  world.add_input(0, Eigen::Vector2d::UnitX());
  MoreauJeanStepper with_input(world, {});
  EXPECT_NE(error_of([&] {
              with_input.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), {}, 0.01);
            }).find("no input function"),
            std::string::npos);

  const auto negative_mu = box_on_ground(-0.1);
  MoreauJeanStepper bad(negative_mu, {});
  EXPECT_NE(error_of([&] {
              bad.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), {}, 0.01);
            }).find("friction"),
            std::string::npos);
  const auto bad_e = box_on_ground(0.5, 1.5);
  MoreauJeanStepper bad2(bad_e, {});
  EXPECT_NE(error_of([&] {
              bad2.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), {}, 0.01);
            }).find("restitution"),
            std::string::npos);
}

// A block sliding on two corners needs more than one sweep; with one allowed the solve fails.
TEST(MoreauStepperApi, NonConvergenceStopsOrWarns) {
  const auto world = box_on_ground();
  MoreauJeanOptions options;
  options.max_iterations = 1;
  options.tolerance = 1e-14;
  options.record_steps = true;
  const Eigen::Vector3d q0(0, 0.1, 0), v0(2, 0, 0);
  {
    MoreauJeanStepper stepper(world, options);
    const auto result = stepper.simulate(q0, v0, {}, 0.1);
    EXPECT_EQ(result.status, RunStatus::kSolverFailed);
    EXPECT_NE(result.message.find("contact solver"), std::string::npos) << result.message;
    EXPECT_EQ(result.summary.solver_failures, 1);
    EXPECT_EQ(result.summary.steps, 0);  // the failing step is not applied
    EXPECT_EQ(result.final_state.q, q0);
    ASSERT_EQ(result.steps.size(), 1u);
    EXPECT_FALSE(result.steps[0].converged);
  }
  {
    options.on_failure = OnFailure::kWarn;
    MoreauJeanStepper stepper(world, options);
    const auto result = stepper.simulate(q0, v0, {}, 0.1);
    EXPECT_EQ(result.status, RunStatus::kCompleted) << result.message;
    EXPECT_EQ(result.summary.steps, 100);
    EXPECT_GT(result.summary.solver_failures, 0);
    EXPECT_GT(result.summary.worst_residual, 1e-14);
  }
}

TEST(MoreauStepperApi, LastStepLandsOnDuration) {
  const auto world = box_on_ground();
  MoreauJeanOptions options;
  options.dt = 0.003;
  MoreauJeanStepper stepper(world, options);
  const auto result =
      stepper.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), {}, 0.01);
  ASSERT_TRUE(result.succeeded());
  EXPECT_EQ(result.summary.steps, 4);
  EXPECT_DOUBLE_EQ(result.final_state.t, 0.01);
}

TEST(MoreauStepperApi, WarmStartReusesPreviousImpulses) {
  // A resting box poses the same problem every step: warm-started, it is solved at once.
  const auto world = box_on_ground();
  MoreauJeanOptions options;
  options.record_impulses = true;
  options.record_steps = true;
  MoreauJeanStepper stepper(world, options);
  const auto result =
      stepper.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), {}, 0.02);
  ASSERT_TRUE(result.succeeded());
  ASSERT_EQ(result.impulses.size(), 20u);
  ASSERT_EQ(result.steps.size(), 20u);
  for (std::size_t k = 1; k < result.steps.size(); ++k)
    EXPECT_LE(result.steps[k].solver_iterations, 2);
  // Each step's normal impulses carry the box's weight over the step: Σ r_n = m g h.
  for (const auto& step : result.impulses) {
    double total = 0.0;
    for (const auto& c : step) total += c.r_n;
    EXPECT_NEAR(total, 9.81 * 1e-3, 1e-12);
  }
}

TEST(MoreauStepperApi, NewContactStartsFromZeroImpulse) {
  // A disk sliding on the ground without gravity: its contact is active (gap 0, no normal
  // velocity) and r = 0 solves it (u_n = 0, and the cone of r_n = 0 holds only r = 0). A
  // contact met for the first time starts from r = 0, so the solve ends at its entry.
  const PlanarTestWorld world({{"disk", 1.0, 0.1, 0, 0}}, 0.0, 0.5, 0.0);
  MoreauJeanOptions options;
  options.record_impulses = true;
  options.record_steps = true;
  MoreauJeanStepper stepper(world, options);
  const auto result =
      stepper.simulate(Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d(1, 0, 0), {}, options.dt);
  ASSERT_TRUE(result.succeeded());
  ASSERT_EQ(result.impulses.size(), 1u);
  ASSERT_EQ(result.impulses[0].size(), 1u);
  EXPECT_EQ(result.steps[0].solver_iterations, 0);
  EXPECT_EQ(result.impulses[0][0].r_n, 0.0);
  EXPECT_EQ(result.final_state.v, Eigen::Vector3d(1, 0, 0));
}

TEST(MoreauStepperApi, EnergyNeverRisesAndPenetrationScalesWithStep) {
  // A ball dropped on the ground, e = 0: no input, so E_{k+1} ≤ E_k up to the solver
  // tolerance. With the default activation γ = θ = 1/2 the impact step starts from a gap
  // g ∈ (−(1 − γ) h V, γ h V] (active: g − γ h V ≤ 0; the step before was not) and moves the
  // centre by h v_k / 2 (θ = 1/2, v_{k+1} = 0), so the penetration is h V / 2 − g: at most
  // (3/2 − γ) h V = h V, and over drop heights that sweep the phase its worst case approaches
  // that bound.
  const PlanarTestWorld world({{"ball", 1.0, 0.1, 0, 0}}, 9.81, 0.0, 0.0);
  const double speed = std::sqrt(2 * 9.81 * 0.9);
  for (double dt : {2e-3, 1e-3}) {
    MoreauJeanOptions options;
    options.dt = dt;
    MoreauJeanStepper stepper(world, options);
    double worst = 0.0;
    constexpr int kPhases = 16;
    for (int j = 0; j < kPhases; ++j) {
      const double height = 1.0 + speed * dt * (j + 0.5) / kPhases;
      const auto result =
          stepper.simulate(Eigen::Vector3d(0, height, 0), Eigen::Vector3d::Zero(), {}, 0.6);
      ASSERT_TRUE(result.succeeded());
      EXPECT_LE(result.summary.max_energy_rise, 1e-9);
      EXPECT_LT(result.summary.energy_end, result.summary.energy_start);
      worst = std::max(worst, result.summary.max_penetration);
    }
    const double bound = dt * speed;
    std::printf("ball drop dt %.0e: worst penetration %.3e, bound h V = %.3e\n", dt, worst, bound);
    EXPECT_LE(worst, bound * (1 + 1e-6)) << dt;
    EXPECT_GE(worst, bound / 2) << dt;  // Θ(h): the bound is approached, not just respected
  }
}

TEST(MoreauBlockDiagonalInverse, MatchesDenseInverse) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  const int sizes[] = {3, 6, 1, 3};
  const int total = 13;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(total, total);
  int start = 0;
  for (int s : sizes) {
    Eigen::MatrixXd a(s, s);
    for (int i = 0; i < a.size(); ++i) a.data()[i] = n01(rng);
    dense.block(start, start, s, s) = a * a.transpose() + Eigen::MatrixXd::Identity(s, s);
    start += s;
  }
  const Eigen::SparseMatrix<double> sparse = dense.sparseView();
  const Eigen::MatrixXd inverse = Eigen::MatrixXd(invert_block_diagonal(sparse));
  EXPECT_LT((inverse * dense - Eigen::MatrixXd::Identity(total, total)).norm(), 1e-10);
  EXPECT_EQ(invert_block_diagonal(sparse).nonZeros(), 9 + 36 + 1 + 9);

  dense(3, 3) = -1.0;  // first entry of the 6×6 block
  EXPECT_NE(error_of([&] { invert_block_diagonal(dense.sparseView()); }).find("[3, 8]"),
            std::string::npos);
}

// A block of 1 to 3 rows inverted by Eigen: reciprocals when it is diagonal, else the fixed-size
// Cholesky factorisation solved with the identity.
template <int N>
Eigen::MatrixXd eigen_cholesky_inverse(const Eigen::MatrixXd& block) {
  using Fixed = Eigen::Matrix<double, N, N>;
  return Eigen::LLT<Fixed>(Fixed(block)).solve(Fixed::Identity());
}
Eigen::MatrixXd eigen_fixed_size_inverse(const Eigen::MatrixXd& block) {
  if (block.isDiagonal(0.0)) return block.diagonal().cwiseInverse().asDiagonal();
  switch (block.rows()) {
    case 2:
      return eigen_cholesky_inverse<2>(block);
    case 3:
      return eigen_cholesky_inverse<3>(block);
    default:
      throw std::logic_error("a block of 1 row is diagonal");
  }
}

TEST(MoreauBlockDiagonalInverse, SmallBlocksHaveTheBitsOfEigensCholeskySolve) {
  // Blocks of 1 to 3 rows are inverted by fixed-size code written into M⁻¹'s compressed storage
  // directly. Each must hold, to the bit, what Eigen's own fixed-size inversion gives for that
  // block (the Cholesky solve with the identity, or reciprocals for a diagonal block), in the
  // structure setFromTriplets gives (zeros of the inverse not stored).
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> exponent(-4.0, 4.0);
  std::vector<int> sizes;
  std::vector<Eigen::MatrixXd> blocks;
  for (int k = 0; k < 400; ++k) {
    const int s = 1 + k % 3;
    Eigen::MatrixXd a(s, s);
    for (int i = 0; i < a.size(); ++i) a.data()[i] = n01(rng);
    Eigen::MatrixXd block = a * a.transpose() + 1e-3 * Eigen::MatrixXd::Identity(s, s);
    if (k % 5 == 0) {  // a rigid body's world inertia R D Rᵀ, with D spread over decades
      const Eigen::Matrix3d r = Eigen::Quaterniond(n01(rng), n01(rng), n01(rng), n01(rng))
                                    .normalized()
                                    .toRotationMatrix();
      const Eigen::Vector3d d(std::pow(10.0, exponent(rng)), std::pow(10.0, exponent(rng)),
                              std::pow(10.0, exponent(rng)));
      block = (r * d.asDiagonal() * r.transpose()).topLeftCorner(s, s);
    }
    if (k % 7 == 0) block = Eigen::MatrixXd(block.diagonal().asDiagonal());  // by reciprocals
    sizes.push_back(s);
    blocks.push_back(block);
  }
  int total = 0;
  for (int s : sizes) total += s;
  std::vector<Eigen::Triplet<double>> entries, expected_entries;
  int start = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const int s = sizes[k];
    const Eigen::MatrixXd expected = eigen_fixed_size_inverse(blocks[k]);
    for (int c = 0; c < s; ++c) {
      for (int r = 0; r < s; ++r) {
        if (blocks[k](r, c) != 0.0) entries.emplace_back(start + r, start + c, blocks[k](r, c));
        if (expected(r, c) != 0.0)
          expected_entries.emplace_back(start + r, start + c, expected(r, c));
      }
    }
    start += s;
  }
  Eigen::SparseMatrix<double> matrix(total, total), expected(total, total);
  matrix.setFromTriplets(entries.begin(), entries.end());
  expected.setFromTriplets(expected_entries.begin(), expected_entries.end());
  // Into storage kept from a smaller inverse, as the time stepper keeps it.
  Eigen::SparseMatrix<double> inverse = invert_block_diagonal(matrix.topLeftCorner(6, 6));
  invert_block_diagonal(matrix, BlockFactorization::kCholesky, inverse);
  ASSERT_TRUE(inverse.isCompressed());
  ASSERT_EQ(inverse.nonZeros(), expected.nonZeros());
  int differing = 0;
  for (int j = 0; j <= total; ++j)
    differing += inverse.outerIndexPtr()[j] != expected.outerIndexPtr()[j];
  for (Eigen::Index k = 0; k < expected.nonZeros(); ++k)
    differing += inverse.innerIndexPtr()[k] != expected.innerIndexPtr()[k] ||
                 inverse.valuePtr()[k] != expected.valuePtr()[k];
  EXPECT_EQ(differing, 0);
}

TEST(MoreauBlockDiagonalInverse, FillInBeyondTheMatrixsEntriesGrowsTheStorage) {
  // A tridiagonal 6 × 6 block has 16 entries and a dense inverse of 36, more than the room of
  // the matrix's entries and one per row (22): the storage must grow mid-way, keeping the
  // entries already written.
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(8, 8);
  dense(0, 0) = 2.0;
  for (int i = 1; i < 7; ++i) {
    dense(i, i) = 4.0;
    if (i > 1) dense(i, i - 1) = dense(i - 1, i) = -1.0;
  }
  dense(7, 7) = 0.5;
  const Eigen::SparseMatrix<double> sparse = dense.sparseView();
  ASSERT_EQ(sparse.nonZeros(), 18);
  Eigen::SparseMatrix<double> inverse;
  invert_block_diagonal(sparse, BlockFactorization::kCholesky, inverse);
  EXPECT_EQ(inverse.nonZeros(), 1 + 36 + 1);
  EXPECT_LT((Eigen::MatrixXd(inverse) * dense - Eigen::MatrixXd::Identity(8, 8)).norm(), 1e-14);
  EXPECT_EQ(inverse.coeff(0, 0), 0.5);
  EXPECT_EQ(inverse.coeff(7, 7), 2.0);
}

TEST(MoreauStepperApi, EnergyBeforeAStepIsThatOfTheStateItStartsFrom) {
  // The energy before a step repeats the last step's energy after it when the step starts from
  // the state that step produced; a state changed in between has its own.
  const PlanarTestWorld world({{"ball", 2.0, 0.1, 0, 0}}, 9.81, 0.0, 0.0);
  MoreauJeanStepper stepper(world, MoreauJeanOptions{});
  MoreauJeanState state{0.0, Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d(0.5, 0, 0)};
  const StepReport first = stepper.step(state, {});
  const StepReport second = stepper.step(state, {});
  EXPECT_EQ(second.statistics.energy_before, first.statistics.energy_after);
  EXPECT_EQ(second.statistics.energy_after, world.energy(state.q, state.v));
  state.v(0) = 3.0;  // in flight, v_x was 0.5: ½ m Δ(v_x²) = ½ · 2 · (9 − 0.25) more energy
  const double changed = world.energy(state.q, state.v);
  const StepReport third = stepper.step(state, {});
  EXPECT_EQ(third.statistics.energy_before, changed);
  EXPECT_NEAR(changed - second.statistics.energy_after, 8.75, 1e-12);
  state.q(1) += 0.5;  // m g Δy = 2 · 9.81 · 0.5 more potential energy
  const StepReport fourth = stepper.step(state, {});
  EXPECT_NEAR(fourth.statistics.energy_before - third.statistics.energy_after, 9.81, 1e-12);
}

// Three disks in a row on the ground, at a state with five contacts: one with the ground each
// (a block) and two between the disks (two blocks each), the ground contacts first.
struct ThreeDisksInARow {
  PlanarTestWorld world{
      {{"a", 1.0, 0.1, 0, 0}, {"b", 2.0, 0.1, 0, 0}, {"c", 0.5, 0.1, 0, 0}}, 9.81, 0.4, 0.5};
  Eigen::VectorXd q{{0, 0.1, 0, 0.2, 0.1, 0, 0.4, 0.1, 0}};
  Eigen::VectorXd v{{1, -1, 2, 0, -0.5, 0, -1, 0.3, 1}};
  std::vector<model::Contact<double>> contacts;
  Eigen::SparseMatrix<double> minv;

  ThreeDisksInARow() {
    world.find_contacts(q, v, 1e-6, contacts);
    minv = invert_block_diagonal(world.mass_matrix(q));
  }
};

TEST(MoreauDelassus, AFormedProblemInAKeptSystemHasNoFactorBlocks) {
  // A system that held a factored problem, then a formed one: the formed problem keeps nothing
  // of the factored one's blocks (a solver would read none, but the problem says what it is).
  const ThreeDisksInARow disks;
  const auto& [world, q, v, contacts, minv] = disks;
  DelassusSystem kept;
  assemble_delassus(contacts, 1, minv, v, v, 0, /*factored=*/true, kept);
  ASSERT_FALSE(kept.problem.factor_blocks.empty());
  assemble_delassus(contacts, 1, minv, v, v, 0, /*factored=*/false, kept);
  EXPECT_TRUE(kept.problem.is_sparse);
  EXPECT_FALSE(kept.problem.is_factored);
  EXPECT_TRUE(kept.problem.factor_blocks.empty());
  EXPECT_TRUE(kept.problem.factor_blocks.values.empty());
}

TEST(MoreauDelassus, DenseAndSparseMatchDenseFormula) {
  const ThreeDisksInARow disks;
  const auto& [world, q, v, contacts, minv] = disks;
  const Eigen::VectorXd v_free = v + Eigen::VectorXd::Constant(9, 0.01);
  ASSERT_EQ(contacts.size(), 5u);
  const auto dense = assemble_delassus(contacts, 1, minv, v, v_free, 1000);
  const auto sparse = assemble_delassus(contacts, 1, minv, v, v_free, 0);
  ASSERT_FALSE(dense.problem.is_sparse);
  ASSERT_TRUE(sparse.problem.is_sparse);

  Eigen::MatrixXd J(10, 9);
  Eigen::VectorXd expected_q(10);
  for (int i = 0; i < 5; ++i) {
    J.row(2 * i) = contacts[i].normal_direction(9).transpose();
    J.row(2 * i + 1) = contacts[i].tangent_directions(9).transpose();
    const double zeta_n = contacts[i].relative_velocity(v)(0);
    expected_q(2 * i) = J.row(2 * i).dot(v_free) + 0.5 * std::min(zeta_n, 0.0);
    expected_q(2 * i + 1) = J.row(2 * i + 1).dot(v_free);
  }
  const Eigen::MatrixXd minv_dense = Eigen::MatrixXd(world.mass_matrix(q)).inverse();
  const Eigen::MatrixXd W = J * minv_dense * J.transpose();
  EXPECT_LT((dense.problem.dense_W - W).norm(), 1e-12);
  EXPECT_LT((Eigen::MatrixXd(sparse.problem.sparse_W) - W).norm(), 1e-12);
  EXPECT_LT((Eigen::MatrixXd(sparse.inverse_mass_jacobian_t) - minv_dense * J.transpose()).norm(),
            1e-12);
  EXPECT_LT((dense.problem.q - expected_q).norm(), 1e-12);
  EXPECT_EQ(dense.problem.mu, Eigen::VectorXd::Constant(5, 0.4));

  // Factored for Gauss–Seidel, by its factor blocks alone: the same W once formed, the same J
  // and M⁻¹Jᵀ, the same q, and M⁻¹Jᵀ r for the velocity update.
  const auto factored = assemble_delassus(contacts, 1, minv, v, v_free, 0, /*factored=*/true);
  ASSERT_TRUE(factored.problem.is_factored);
  EXPECT_TRUE(factored.problem.factored_by_blocks_only());
  EXPECT_EQ(factored.problem.factor_blocks.velocities, 9);
  EXPECT_LT((Eigen::MatrixXd(solvers::formed_delassus(factored.problem).sparse_W) - W).norm(),
            1e-12);
  Eigen::SparseMatrix<double, Eigen::RowMajor> J_from_blocks;
  Eigen::SparseMatrix<double> minv_jt_from_blocks;
  solvers::sparse_factors_from_blocks(factored.problem.factor_blocks, 2, J_from_blocks,
                                      minv_jt_from_blocks);
  EXPECT_EQ(Eigen::MatrixXd(J_from_blocks), J);
  EXPECT_LT((Eigen::MatrixXd(minv_jt_from_blocks) - minv_dense * J.transpose()).norm(), 1e-12);
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(10, -1.0, 2.0);
  solvers::CapacityVector impulse_velocity;
  factored.write_impulse_velocity(r, impulse_velocity);
  EXPECT_LT((impulse_velocity - minv_dense * J.transpose() * r).norm(), 1e-12);
  EXPECT_LT((factored.problem.q - expected_q).norm(), 1e-12);
  // Factored whatever its size: a problem small enough to be dense for other solvers is not
  // formed for one that sweeps the factors, and has the same factors.
  const auto small = assemble_delassus(contacts, 1, minv, v, v_free, 1000, /*factored=*/true);
  ASSERT_TRUE(small.problem.is_factored);
  EXPECT_FALSE(small.problem.is_sparse);
  EXPECT_EQ(small.problem.dense_W.size(), 0);
  EXPECT_LT((Eigen::MatrixXd(solvers::formed_delassus(small.problem).sparse_W) - W).norm(), 1e-12);

  // The bodies' blocks of M⁻¹ are disjoint: W was formed block by block. With M⁻¹ coupling
  // bodies a and c (a symmetric positive definite perturbation), the block assembly declines
  // and the general products give J M⁻¹ Jᵀ for that matrix.
  Eigen::SparseMatrix<double, Eigen::RowMajor> J_blocks;
  Eigen::SparseMatrix<double, Eigen::RowMajor> W_blocks;
  Eigen::SparseMatrix<double> minv_jt;
  EXPECT_TRUE(assemble_block_sparse_delassus(contacts, 2, minv, &J_blocks, &W_blocks, &minv_jt));
  // J row by row equals the general (triplet) assembly, entry for entry and in its pattern.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> J_general =
      assemble_contact_jacobian(contacts, 9, 1);
  EXPECT_EQ(Eigen::MatrixXd(J_blocks), Eigen::MatrixXd(J_general));
  EXPECT_EQ(J_blocks.nonZeros(), J_general.nonZeros());
  EXPECT_LT((Eigen::MatrixXd(J_blocks) - J).norm(), 1e-14);
  EXPECT_TRUE(J_blocks.isCompressed());
  EXPECT_TRUE(minv_jt.isCompressed());
  // Into the same matrices again, for fewer contacts: their kept storage holds exactly the new
  // problem's entries.
  const std::span<const model::Contact<double>> first_three(contacts.data(), 3);
  EXPECT_TRUE(assemble_block_sparse_delassus(first_three, 2, minv, &J_blocks, &W_blocks, &minv_jt));
  const Eigen::SparseMatrix<double, Eigen::RowMajor> J_three =
      assemble_contact_jacobian(first_three, 9, 1);
  EXPECT_EQ(J_blocks.nonZeros(), J_three.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(J_blocks), Eigen::MatrixXd(J_three));
  EXPECT_LT((Eigen::MatrixXd(minv_jt) - minv_dense * Eigen::MatrixXd(J_three).transpose()).norm(),
            1e-14);
  Eigen::MatrixXd coupled = minv_dense;
  coupled(0, 6) = coupled(6, 0) = 0.1;
  const Eigen::SparseMatrix<double> coupled_sparse = coupled.sparseView();
  EXPECT_FALSE(
      assemble_block_sparse_delassus(contacts, 2, coupled_sparse, &J_blocks, &W_blocks, &minv_jt));
  const auto general = assemble_delassus(contacts, 1, coupled_sparse, v, v_free, 0);
  EXPECT_LT((Eigen::MatrixXd(general.problem.sparse_W) - J * coupled * J.transpose()).norm(),
            1e-12);
  EXPECT_LT((Eigen::MatrixXd(general.inverse_mass_jacobian_t) - coupled * J.transpose()).norm(),
            1e-12);
}

TEST(MoreauDelassus, FactorBlocksAreTheFactorsInRangeOrderWhateverTheStorageHeld) {
  const ThreeDisksInARow disks;
  const auto& [world, q, v, contacts, minv] = disks;
  ASSERT_EQ(contacts.size(), 5u);
  const Eigen::MatrixXd minv_dense = Eigen::MatrixXd(minv);
  // Each contact's blocks listed in reverse: the assembly puts them in the order of their
  // velocity ranges.
  std::vector<model::Contact<double>> reversed = contacts;
  int two_block_contacts = 0;
  for (auto& c : reversed) {
    if (c.blocks.size() == 2) ++two_block_contacts;
    std::reverse(c.blocks.begin(), c.blocks.end());
  }
  ASSERT_EQ(two_block_contacts, 2);
  // Into a system that held a larger problem first (its five contacts' blocks), then the
  // reversed last three (a ground contact and both disk–disk ones, the ground contacts coming
  // first): the blocks describe those three only.
  DelassusSystem kept;
  assemble_delassus(contacts, 1, minv, v, v, 0, /*factored=*/true, kept);
  const std::span<const model::Contact<double>> three(reversed.data() + 2, 3);
  assemble_delassus(three, 1, minv, v, v, 0, /*factored=*/true, kept);
  const solvers::FactorBlocks& blocks = kept.problem.factor_blocks;
  ASSERT_EQ(blocks.contact_start.size(), 4u);
  EXPECT_EQ(blocks.contact_start.front(), 0);
  // Contact i's block on the range [first, first + size): J_ib (2 × size) then H_ib = M⁻¹_b J_ibᵀ
  // (size × 2), both column-major, equal to the dense products; ranges ascending.
  const std::span<const model::Contact<double>> original(contacts.data() + 2, 3);
  ASSERT_EQ(original[1].blocks.size() + original[2].blocks.size(), 4u);
  std::size_t values = 0;
  for (int i = 0; i < 3; ++i) {
    Eigen::MatrixXd J(2, 9);
    J.row(0) = original[i].normal_direction(9).transpose();
    J.row(1) = original[i].tangent_directions(9).transpose();
    const Eigen::MatrixXd H = minv_dense * J.transpose();
    const int first_block = blocks.contact_start[static_cast<std::size_t>(i)];
    const int end_block = blocks.contact_start[static_cast<std::size_t>(i) + 1];
    EXPECT_EQ(end_block - first_block, static_cast<int>(original[i].blocks.size())) << i;
    int previous_first = -1;
    for (int b = first_block; b < end_block; ++b) {
      const auto k = static_cast<std::size_t>(b);
      const int first = blocks.first_velocity[k], size = blocks.size[k];
      EXPECT_GT(first, previous_first) << "contact " << i;
      previous_first = first;
      ASSERT_EQ(size, 3);
      const double* entries = &blocks.values[static_cast<std::size_t>(blocks.offset[k])];
      const Eigen::Map<const Eigen::MatrixXd> J_block(entries, 2, size);
      const Eigen::Map<const Eigen::MatrixXd> H_block(entries + 2 * size, size, 2);
      EXPECT_EQ(J_block, J.middleCols(first, size)) << "contact " << i;
      EXPECT_LT((H_block - H.middleRows(first, size)).norm(), 1e-14) << "contact " << i;
      values += static_cast<std::size_t>(4 * size);
    }
  }
  EXPECT_EQ(blocks.values.size(), values);
  EXPECT_EQ(blocks.first_velocity.size(), static_cast<std::size_t>(blocks.contact_start.back()));
  // The same as a fresh system's for the contacts as found.
  DelassusSystem fresh;
  assemble_delassus(original, 1, minv, v, v, 0, /*factored=*/true, fresh);
  EXPECT_EQ(blocks.contact_start, fresh.problem.factor_blocks.contact_start);
  EXPECT_EQ(blocks.first_velocity, fresh.problem.factor_blocks.first_velocity);
  EXPECT_EQ(blocks.size, fresh.problem.factor_blocks.size);
  EXPECT_EQ(blocks.offset, fresh.problem.factor_blocks.offset);
  EXPECT_EQ(blocks.values, fresh.problem.factor_blocks.values);
  EXPECT_EQ(blocks.velocities, fresh.problem.factor_blocks.velocities);
  EXPECT_TRUE(kept.problem.factored_by_blocks_only());
}

TEST(MoreauDelassus, AKeptSystemKeepsItsVectorsStorageWhenTheContactsAreFewerOrMore) {
  // A time stepper's active count goes up and down; the problem's q and μ and J v_k stay in
  // the storage of the largest count met, and hold what a fresh assembly gives, to the bit.
  const ThreeDisksInARow disks;
  const auto& [world, q, v, contacts, minv] = disks;
  ASSERT_EQ(contacts.size(), 5u);
  const Eigen::VectorXd v_free = v + Eigen::VectorXd::Constant(9, -0.3);
  DelassusSystem kept;
  assemble_delassus(contacts, 1, minv, v, v_free, 0, /*factored=*/true, kept);
  const double* q_storage = kept.problem.q.data();
  const double* mu_storage = kept.problem.mu.data();
  const double* zeta_storage = kept.zeta_start.data();
  for (const std::size_t count : {3u, 1u, 5u, 4u}) {
    const std::span<const model::Contact<double>> some(contacts.data(), count);
    assemble_delassus(some, 1, minv, v, v_free, 0, /*factored=*/true, kept);
    const DelassusSystem fresh = assemble_delassus(some, 1, minv, v, v_free, 0, /*factored=*/true);
    ASSERT_EQ(kept.problem.q.size(), static_cast<Eigen::Index>(2 * count));
    EXPECT_EQ(kept.problem.q.data(), q_storage) << count;
    EXPECT_EQ(kept.problem.mu.data(), mu_storage) << count;
    EXPECT_EQ(kept.zeta_start.data(), zeta_storage) << count;
    EXPECT_EQ(kept.problem.q, fresh.problem.q) << count;
    EXPECT_EQ(kept.problem.mu, fresh.problem.mu) << count;
    EXPECT_EQ(kept.zeta_start, fresh.zeta_start) << count;
  }
}

// M⁻¹Jᵀ as the block assembly forms it, against every entry summed in full: from +0 over the
// body's velocities in ascending order, zeros of M⁻¹ included. Compared bit for bit (sign of zero
// too): leaving out the zeros of M⁻¹ must not change a bit.
void expect_full_sums(std::span<const model::Contact<double>> contacts, int nv, int tangent_dim,
                      const Eigen::SparseMatrix<double>& minv, int body_size) {
  const int dim = 1 + tangent_dim;
  Eigen::SparseMatrix<double, Eigen::RowMajor> J_blocks;
  Eigen::SparseMatrix<double> minv_jt;
  ASSERT_TRUE(assemble_block_sparse_delassus(contacts, dim, minv, &J_blocks, nullptr, &minv_jt));
  const Eigen::MatrixXd J = Eigen::MatrixXd(assemble_contact_jacobian(contacts, nv, tangent_dim));
  const Eigen::MatrixXd M_inv = Eigen::MatrixXd(minv);
  const Eigen::MatrixXd H = Eigen::MatrixXd(minv_jt);
  int compared = 0;
  for (int column = 0; column < J.rows(); ++column)
    for (int velocity = 0; velocity < nv; ++velocity) {
      const int first = velocity - velocity % body_size;                  // the body's range
      if (J.row(column).segment(first, body_size).isZero(0.0)) continue;  // no block there
      double sum = 0.0;
      for (int c = first; c < first + body_size; ++c) sum += M_inv(velocity, c) * J(column, c);
      EXPECT_EQ(test_support::bits(H(velocity, column)), test_support::bits(sum))
          << "M⁻¹Jᵀ(" << velocity << ", " << column << ") = " << H(velocity, column) << ", " << sum;
      ++compared;
    }
  EXPECT_GT(compared, 0);
}

TEST(MoreauDelassus, InverseMassJacobianHasTheBitsOfTheFullSums) {
  // Disks: M⁻¹ diagonal per body.
  const ThreeDisksInARow disks;
  expect_full_sums(disks.contacts, 9, 1, disks.minv, 3);
  // The same bodies with M⁻¹'s blocks full (symmetric positive definite perturbations).
  Eigen::MatrixXd full = Eigen::MatrixXd(disks.minv);
  for (int body = 0; body < 3; ++body) {
    full.block(3 * body, 3 * body, 3, 3) += Eigen::MatrixXd::Constant(3, 3, 0.01 * (body + 1));
    full(3 * body, 3 * body + 1) = full(3 * body + 1, 3 * body) -= 0.003;
  }
  expect_full_sums(disks.contacts, 9, 1, full.sparseView(), 3);

  // Spheres turned at random: M⁻¹ diagonal on the translations, a full 3 × 3 world inertia's
  // inverse on the rotations.
  const model::spatial::SpatialRigidBodySystem<double> spheres(
      model::spatial::make_sphere_pile(60, 4));
  Eigen::VectorXd sphere_q = spheres.initial_positions();
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < spheres.num_bodies(); ++i) {
    const Eigen::Vector4d turn(normal(random), normal(random), normal(random), normal(random));
    sphere_q.segment<4>(7 * i + 3) = turn.normalized();
  }
  const Eigen::VectorXd sphere_v = Eigen::VectorXd::Zero(spheres.num_velocities());
  std::vector<model::Contact<double>> sphere_contacts;
  spheres.find_contacts(sphere_q, sphere_v, 0.5, sphere_contacts);  // neighbours within 0.5 m
  ASSERT_GT(sphere_contacts.size(), 60u);
  const Eigen::SparseMatrix<double> sphere_minv =
      invert_block_diagonal(spheres.mass_matrix(sphere_q));
  // Rotational blocks with entries off their diagonal: the case with terms left out and kept.
  ASSERT_NE(Eigen::MatrixXd(sphere_minv)(3, 4), 0.0);
  expect_full_sums(sphere_contacts, spheres.num_velocities(), 2, sphere_minv, 6);
}

}  // namespace
}  // namespace impactbench::engines::moreau_jean
