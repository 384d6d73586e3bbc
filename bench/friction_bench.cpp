// Every friction solver on piles of disks (planar) and spheres (spatial), 10 to 10,000
// contacts: dense W up to 500 contacts, block-sparse beyond. Names:
//   friction/<solver>/<planar|spatial>/<contacts>
// Skipped as infeasible: Lemke beyond 300 contacts (dense pivoting on (k+2)·n variables), PGS
// on the LCP form beyond 1000, and the Newton method beyond 3000 (sparse LU of the 3n system
// per step).
#include <string>

#include <benchmark/benchmark.h>

#include "common/friction_bench_run.hpp"
#include "common/friction_piles.hpp"
#include "common/registered_main.hpp"

namespace {

bool feasible(const std::string& solver, int contacts) {
  if (solver == "lemke") return contacts <= 300;
  if (solver == "pgs") return contacts <= 1000;
  if (solver == "nsn") return contacts <= 3000;
  return true;
}

void register_all() {
  for (const auto& info : impactbench::solvers::friction_solvers()) {
    for (const int dimension : {2, 3}) {
      for (const int contacts : {10, 30, 100, 300, 1000, 3000, 10000}) {
        if (!feasible(info.name, contacts)) continue;
        const std::string name = "friction/" + info.name + "/" +
                                 (dimension == 2 ? "planar" : "spatial") + "/" +
                                 std::to_string(contacts);
        benchmark::RegisterBenchmark(
            name.c_str(),
            [solver = info.name, dimension, contacts](benchmark::State& state) {
              impactbench::bench::run_friction_solve(
                  state, impactbench::bench::cached_pile_problem(dimension, contacts), solver);
            })
            ->Iterations(1)
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, register_all);
}
