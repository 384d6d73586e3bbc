#include "tools/cli/sweep_pool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/sweep_progress.hpp"
#include "tools/cli/sweep_result.hpp"
#include "tools/compare/stop_signal_handler.hpp"

namespace impactbench::cli {
namespace {

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int) {
  g_stop = 1;
}

/// SIGINT and SIGTERM set g_stop while the pool runs; the previous handlers come back after.
class StopSignals {
 public:
  StopSignals() : handler_(on_stop_signal) { g_stop = 0; }

 private:
  compare::StopSignalHandler handler_;
};

struct Worker {
  pid_t pid;
  const PoolPoint* point;
  Clock::time_point deadline;
  bool timed_out = false;
};

std::filesystem::path log_path(const std::filesystem::path& dir, const std::string& id) {
  return dir / "logs" / (id + ".log");
}

// The worker is a fork of this process, not a new program: a point then costs no process start
// (loading and relocating some 60 shared libraries took about 85 % of a short point's time)
// and keeps its isolation (its own process, killed at its time limit, its crash its own). The
// worker writes its pid as the first line of DIR/logs/<id>.log, then compare's "running ..."
// lines and any error; it keeps none of this process's files open (the sweep's lock
// included) and takes the default actions for SIGINT and SIGTERM.
pid_t fork_worker(const PoolOptions& options, const PoolPoint& point) {
  const std::string& id = point.id;
  const std::string log = log_path(options.dir, id).string();
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw CliError("sweep: cannot start a worker (fork failed)", kExitFailure);
  if (pid > 0) return pid;
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  close_range(3, ~0U, 0);
  const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out < 0) {
    // Still the pool's stderr: the one place left to say why this point has no result.
    const std::string why = "\nsweep: cannot write the log " + log + " of point " + id + ": " +
                            std::strerror(errno) + "\n";
    (void)!write(2, why.data(), why.size());
    _exit(kExitFailure);
  }
  const int null = open("/dev/null", O_WRONLY);
  if (null < 0 || dup2(null, 1) < 0 || dup2(out, 2) < 0) _exit(kExitFailure);
  close(out);
  close(null);
  std::cerr << "sweep-point " << id << " pid " << getpid() << std::endl;
  int code = 0;
  try {
    point.run();
  } catch (const CliError& error) {
    std::cerr << "impactbench: " << error.what() << std::endl;
    code = error.exit_code();
  } catch (const std::exception& error) {
    std::cerr << "impactbench: " << error.what() << std::endl;
    code = kExitFailure;
  }
  std::cout.flush();
  std::cerr.flush();
  _exit(code);
}

std::string ending(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  return "exited with code " + std::to_string(WEXITSTATUS(status));
}

}  // namespace

PoolOutcome run_pool(const std::vector<PoolPoint>& points, const PoolOptions& options) {
  StopSignals signals;
  PoolOutcome outcome;
  SweepProgress progress(points.size(), options.progress);
  std::vector<Worker> workers;
  std::filesystem::create_directories(options.dir / "logs");
  std::size_t next = 0;
  const auto limit = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options.time_limit > 0 ? options.time_limit : 1e9));
  while ((next < points.size() || !workers.empty()) && !g_stop) {
    while (next < points.size() && workers.size() < options.jobs && !g_stop) {
      const PoolPoint& point = points[next++];
      workers.push_back({fork_worker(options, point), &point, Clock::now() + limit});
    }
    bool reaped = false;
    for (auto it = workers.begin(); it != workers.end();) {
      int status = 0;
      const pid_t done = waitpid(it->pid, &status, WNOHANG);
      if (done == 0) {
        if (!it->timed_out && Clock::now() > it->deadline) {
          kill(it->pid, SIGKILL);
          it->timed_out = true;
        }
        ++it;
        continue;
      }
      reaped = true;
      std::error_code ignored;
      std::filesystem::remove_all(options.dir / "scratch" / it->point->id, ignored);
      if (it->timed_out) {
        std::filesystem::remove(log_path(options.dir, it->point->id), ignored);
        write_point_result(options.dir, {it->point->id,
                                         it->point->hash,
                                         "timeout",
                                         "passed its time limit of " +
                                             output::number_text(options.time_limit) + " s",
                                         "",
                                         0,
                                         {}});
        ++outcome.ran;
        ++outcome.failed;
      } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        std::string problem;
        const auto result = read_point_result(result_path(options.dir, it->point->id), problem);
        ++outcome.ran;
        if (result && result->status != "ok") ++outcome.failed;
        std::filesystem::remove(log_path(options.dir, it->point->id), ignored);
      } else {
        std::cerr << "\nsweep: the worker of point " << it->point->id << " " << ending(status)
                  << "; no result (a resume reruns it; its output: "
                  << log_path(options.dir, it->point->id).string() << ")\n";
        ++outcome.lost;
      }
      it = workers.erase(it);
    }
    progress.update(outcome.ran + outcome.lost, outcome.failed + outcome.lost, reaped);
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (g_stop) {
    outcome.interrupted = true;
    for (const Worker& worker : workers) kill(worker.pid, SIGTERM);
    for (const Worker& worker : workers) waitpid(worker.pid, nullptr, 0);
  }
  if (!options.shared) remove_empty_work_folders(options.dir);
  return outcome;
}

void remove_empty_work_folders(const std::filesystem::path& dir) {
  // Left empty unless a worker ended without a result (or was killed mid-point).
  std::error_code ignored;
  std::filesystem::remove(dir / "logs", ignored);
  std::filesystem::remove(dir / "scratch", ignored);
}

}  // namespace impactbench::cli
