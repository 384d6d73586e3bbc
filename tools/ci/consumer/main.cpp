// A program built against an installed impactbench (tools/ci/check_install.sh): loads a scenario
// file, resolves Moreau–Jean's settings as `impactbench run` does, runs 0.1 s through the
// engine registry and prints the final ball height.
#include <cstdio>

#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENARIO.toml\n");
    return 2;
  }
  const auto scenario = impactbench::scenario::load_scenario(argv[1]);
  impactbench::engines::SettingsRequest request;
  request.duration = 0.1;
  const auto options = impactbench::engines::resolve_run_options(impactbench::engine_name::kMoreau,
                                                                 scenario, request);
  const auto result =
      impactbench::adapters::run_engine(impactbench::engine_name::kMoreau, scenario, options);
  std::printf("%zu samples, final height %g m\n", result.trajectory.samples.size(),
              result.trajectory.samples.back().q[1]);
  return 0;
}
