// A program built against an installed impactbench (tools/ci/check_install.sh): loads a scenario
// file, runs it with Moreau–Jean through the engine registry, prints the final ball height.
#include <cstdio>

#include "tools/adapters/engine_registry.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENARIO.toml\n");
    return 2;
  }
  const auto scenario = impactbench::scenario::load_scenario(argv[1]);
  impactbench::engines::RunOptions options;
  options.engine = "moreau";
  options.dt = scenario.dt;
  options.tolerance = scenario.tolerance;
  options.duration = 0.1;
  const auto result = impactbench::adapters::run_engine("moreau", scenario, options);
  std::printf("%zu samples, final height %g m\n", result.trajectory.samples.size(),
              result.trajectory.samples.back().q[1]);
  return 0;
}
