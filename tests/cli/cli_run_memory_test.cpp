// A run's memory does not grow with its step count: nothing per step is kept (the trajectory is
// streamed, the step figures are running aggregates). Measured as the peak resident memory of
// the program on the same scenario for 10^5 and 10^6 steps.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

namespace impactbench {
namespace {

/// Peak resident memory [bytes] of `run bouncing_ball` under `engine` for `duration` seconds
/// at a step of 1e-5 s, its rows sent to /dev/null.
long peak_memory_of_run(const std::string& engine, const std::string& duration) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl(IMPACTBENCH_CLI, IMPACTBENCH_CLI, "run", "bouncing_ball", "--engine", engine.c_str(),
            "--dt", "1e-5", "--duration", duration.c_str(), "--out", "/dev/null",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  ::wait4(child, &status, 0, &usage);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << engine << " " << duration;
  return usage.ru_maxrss * 1024L;  // Linux reports kilobytes
}

TEST(RunMemory, MoreauJeanDoesNotGrowWithTheStepCount) {
#ifdef __SANITIZE_ADDRESS__
  // AddressSanitizer keeps freed blocks in a quarantine of up to 256 MB by design, so a run's
  // peak memory grows with its allocations there; the release tests measure it.
  GTEST_SKIP() << "peak memory is not the program's own under AddressSanitizer";
#endif
  const long short_run = peak_memory_of_run("moreau", "1");  // 10^5 steps
  const long long_run = peak_memory_of_run("moreau", "10");  // 10^6 steps
  // Anything kept per step costs at least 8 bytes (one double): 9e5 more steps would add
  // 7.2 MB. The bound leaves that much for allocator noise and nothing for per-step storage
  // (76269e6 kept ~90 bytes per step: 81 MB more).
  EXPECT_LT(long_run - short_run, 9e5 * 8)
      << "peak memory " << short_run << " B for 10^5 steps, " << long_run << " B for 10^6";
}

}  // namespace
}  // namespace impactbench
