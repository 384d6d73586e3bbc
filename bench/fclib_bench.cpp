// Every friction solver on every FCLIB problem of share/impactbench/fclib (global ones reduced
// to the local form once, outside the timing). Names: fclib/<solver>/<file stem>.
#include <string>

#include <benchmark/benchmark.h>

#include "common/fclib_collection.hpp"
#include "common/friction_bench_run.hpp"
#include "common/registered_main.hpp"
#include "lib/resources/resource_paths.hpp"

namespace {

void register_all() {
  const auto files =
      impactbench::bench::fclib_collection_files(impactbench::resources::fclib_directory());
  for (const auto& info : impactbench::solvers::friction_solvers()) {
    for (const auto& path : files) {
      const std::string name = "fclib/" + info.name + "/" + path.stem().string();
      benchmark::RegisterBenchmark(
          name.c_str(),
          [solver = info.name, path](benchmark::State& state) {
            impactbench::bench::run_friction_solve(
                state, impactbench::bench::cached_fclib_problem(path).problem, solver);
          })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, register_all);
}
