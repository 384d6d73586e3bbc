// The per-step work of Moreau–Jean with a solver that sweeps the factors, as the stepper does
// it: the problem assembled into a kept system (given by its factor blocks alone), solved into
// a kept result, and M⁻¹Jᵀ r formed for the velocity update. Once the largest number of active
// contacts has been met (twice, see below), a step with that many or fewer allocates nothing: the
// factor blocks, q, μ, J v_k, r, u and the velocity all keep their storage. Counted by the counting
// allocator (tests/support/heap), every malloc of the process included.
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "lib/engines/moreau_jean/block_diagonal_inverse.hpp"
#include "lib/engines/moreau_jean/delassus_assembly.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "tests/support/heap/heap_allocations.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::moreau_jean {
namespace {

using test_support::PlanarTestBody;
using test_support::PlanarTestWorld;

class StepAllocations : public ::testing::TestWithParam<std::string> {};

TEST_P(StepAllocations, NoneOnceTheLargestActiveCountHasBeenMet) {
  // Twelve disks of different masses in a row on the ground, apart: 12 contacts, approaching the
  // ground, each with its own body.
  constexpr int kDisks = 12;
  std::vector<PlanarTestBody> bodies;
  for (int k = 0; k < kDisks; ++k)
    bodies.push_back({"disk" + std::to_string(k), 1.0 + 0.1 * k, 0.1, 0.0, 0.0});
  const PlanarTestWorld world(bodies, 9.81, 0.4, 0.5);
  Eigen::VectorXd q(3 * kDisks), v(3 * kDisks);
  for (int k = 0; k < kDisks; ++k) {
    q.segment<3>(3 * k) << 0.25 * k, 0.1, 0.0;
    v.segment<3>(3 * k) << 0.1 * (k % 3) - 0.1, -0.5, 0.2;
  }
  std::vector<model::Contact<double>> contacts;
  world.find_contacts(q, v, 1e-6, contacts);
  ASSERT_EQ(contacts.size(), 12u);
  const Eigen::SparseMatrix<double> minv = invert_block_diagonal(world.mass_matrix(q));
  const Eigen::VectorXd v_free = v + Eigen::VectorXd::Constant(3 * kDisks, -0.1);

  const solvers::FrictionSolver solver(GetParam());
  ASSERT_TRUE(solver.sweeps_factored_delassus());
  solvers::SolverOptions options;
  options.tolerance = 1e-9;
  options.max_iterations = 5000;
  options.measure_seconds = false;
  DelassusSystem system;
  solvers::SolverResult result;
  solvers::CapacityVector impulse_velocity;
  const auto step = [&](std::size_t count) {
    const std::span<const model::Contact<double>> active(contacts.data(), count);
    assemble_delassus(active, 1, minv, v, v_free, 0, /*factored=*/true, system);
    solver.solve(system.problem, options, nullptr, result);
    system.write_impulse_velocity(result.solution, impulse_velocity);
  };
  // The largest count met twice: the driver's A r at the entry and the sweep's trade their
  // storage (a swap instead of a copy), so each has met the largest size after two solves.
  step(contacts.size());
  step(contacts.size());
  ASSERT_TRUE(system.problem.factored_by_blocks_only());
  ASSERT_TRUE(result.converged()) << result.message;
  for (const std::size_t count : {7u, 12u, 3u, 10u, 1u, 12u}) {
    SCOPED_TRACE(std::to_string(count) + " contacts");
    const long before = heap::allocations();
    step(count);
    const long allocated = heap::allocations() - before;
    ASSERT_TRUE(result.converged()) << result.message;
    EXPECT_EQ(allocated, 0);
    EXPECT_EQ(result.solution.size(), static_cast<Eigen::Index>(2 * count));
    EXPECT_EQ(impulse_velocity.size(), 3 * kDisks);
  }
}

INSTANTIATE_TEST_SUITE_P(SweepingSolvers, StepAllocations, ::testing::Values("nsgs", "prox-gs"),
                         [](const auto& param_info) {
                           return param_info.param == "nsgs" ? std::string("nsgs")
                                                             : std::string("prox_gs");
                         });

}  // namespace
}  // namespace impactbench::engines::moreau_jean
