#include "tools/cli/blas_threads.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string_view>

#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/engine_registry.hpp"

namespace impactbench::cli {

void restart_with_one_blas_thread(char** argv) {
  const adapters::EngineInfo* siconos = adapters::find_engine(engine_name::kSiconos);
  if (!siconos || !siconos->run) return;
  const char* threads = std::getenv("OPENBLAS_NUM_THREADS");
  if (threads && std::string_view(threads) == "1") return;
  if (setenv("OPENBLAS_NUM_THREADS", "1", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

}  // namespace impactbench::cli
