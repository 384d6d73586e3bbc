// Every friction solver on every FCLIB problem of IMPACTBENCH_FCLIB_DIR (global ones reduced
// to the local form once, outside the timing). Names: fclib/<solver>/<file stem>.
#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "common/friction_bench_run.hpp"
#include "solvers/io/fclib_file.hpp"

namespace {

const impactbench::solvers::FrictionProblem& cached_problem(const std::filesystem::path& path) {
  static std::map<std::string, std::unique_ptr<impactbench::solvers::FclibProblem>> cache;
  auto& slot = cache[path.string()];
  if (!slot) {
    slot = std::make_unique<impactbench::solvers::FclibProblem>(
        impactbench::solvers::read_fclib_file(path));
  }
  return slot->problem;
}

void register_all() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(IMPACTBENCH_FCLIB_DIR)) {
    if (entry.path().extension() == ".hdf5") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& info : impactbench::solvers::friction_solvers()) {
    for (const auto& path : files) {
      const std::string name = "fclib/" + info.name + "/" + path.stem().string();
      benchmark::RegisterBenchmark(name.c_str(),
                                   [solver = info.name, path](benchmark::State& state) {
                                     impactbench::bench::run_friction_solve(
                                         state, cached_problem(path), solver);
                                   })
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
