// Cost of PlanarRigidBodySystem::find_contacts (uniform-grid broad phase + narrow phase +
// contact kinematics) on disk piles of 100 ... 10,000 bodies; the fitted complexity should be
// O(N). Counters: bodies, contacts per call.
#include <benchmark/benchmark.h>

#include "common/registered_main.hpp"
#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"

namespace {

using impactbench::model::Contact;
using impactbench::model::planar::make_disk_pile;
using impactbench::model::planar::PlanarRigidBodySystemd;

void BM_FindContactsDiskPile(benchmark::State& state) {
  const int count = static_cast<int>(state.range(0));
  const auto scene = make_disk_pile(count, 1);
  const PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = Eigen::VectorXd::Random(system.num_velocities());
  std::vector<Contact<double>> contacts;
  for (auto _ : state) {
    system.find_contacts(q, v, 0.01, contacts);
    benchmark::DoNotOptimize(contacts.data());
  }
  state.SetComplexityN(count);
  state.counters["bodies"] = count;
  state.counters["contacts"] = static_cast<double>(contacts.size());
}

BENCHMARK(BM_FindContactsDiskPile)
    ->Arg(100)
    ->Arg(300)
    ->Arg(1000)
    ->Arg(3000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, [] {});
}
