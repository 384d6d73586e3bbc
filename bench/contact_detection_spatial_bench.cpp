// Cost of SpatialRigidBodySystem::find_contacts (uniform-grid broad phase + narrow phase) on
// sphere piles of 100 to 10,000 bodies; the fitted complexity should be O(N).
#include <benchmark/benchmark.h>

#include "common/registered_main.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace {

using impactbench::model::Contact;
using impactbench::model::spatial::make_sphere_pile;
using impactbench::model::spatial::SpatialRigidBodySystem;

constexpr double kMargin = 0.01;  // [m]

void BM_FindContactsSpherePile(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const SpatialRigidBodySystem<double> system(make_sphere_pile(count, 1));
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = system.initial_velocities();
  std::vector<Contact<double>> contacts;
  for (auto _ : state) {
    system.find_contacts(q, v, kMargin, contacts);
    benchmark::DoNotOptimize(contacts.data());
  }
  state.SetComplexityN(count);
  state.counters["bodies"] = count;
  state.counters["contacts"] = static_cast<double>(contacts.size());
}

BENCHMARK(BM_FindContactsSpherePile)
    ->RangeMultiplier(2)
    ->Range(100, 10000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, [] {});
}
