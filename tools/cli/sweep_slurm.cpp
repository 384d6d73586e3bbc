#include "tools/cli/sweep_slurm.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>

#include "lib/output/atomic_file.hpp"
#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"

namespace impactbench::cli {
namespace {

/// `text` quoted for sh.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

struct PipeCloser {
  void operator()(FILE* pipe) const {
    if (pipe) pclose(pipe);
  }
};

}  // namespace

std::size_t shard_count(const SweepPlan& plan, const SlurmRequest& request) {
  std::size_t shards = request.shards ? request.shards : plan.spec.slurm_shards;
  if (shards == 0) shards = std::min<std::size_t>(1000, (plan.points.size() + 9) / 10);
  return std::max<std::size_t>(1, std::min(shards, plan.points.size()));
}

std::string slurm_script(const SweepPlan& plan, const SlurmRequest& request,
                         const std::vector<std::size_t>& tasks) {
  const std::size_t shards = shard_count(plan, request);
  const std::size_t concurrency =
      request.concurrency ? request.concurrency : plan.spec.slurm_concurrency;
  const std::string time = request.time.empty() ? plan.spec.slurm_time : request.time;
  const std::string mem = request.mem.empty() ? plan.spec.slurm_mem : request.mem;
  const std::string partition =
      request.partition.empty() ? plan.spec.slurm_partition : request.partition;
  std::string array;
  for (const std::size_t task : tasks) array += (array.empty() ? "" : ",") + std::to_string(task);
  if (concurrency > 0) array += "%" + std::to_string(concurrency);
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe");
  std::string script = "#!/bin/sh\n# impactbench sweep of " + request.spec.string() + "\n";
  script += "#SBATCH --job-name=impactbench-sweep\n";
  script += "#SBATCH --array=" + array + "\n";
  script += "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  script += "#SBATCH --output=" + (request.dir / "slurm" / "task-%A_%a.log").string() + "\n";
  if (!time.empty()) script += "#SBATCH --time=" + time + "\n";
  if (!mem.empty()) script += "#SBATCH --mem=" + mem + "\n";
  if (!partition.empty()) script += "#SBATCH --partition=" + partition + "\n";
  script += "exec " + quoted(program.string()) + " sweep " + quoted(request.spec.string()) +
            " --out " + quoted(request.dir.string()) + " --shard \"$SLURM_ARRAY_TASK_ID/" +
            std::to_string(shards) + "\" --jobs 1";
  if (request.time_limit > 0) script += " --time-limit " + output::number_text(request.time_limit);
  if (request.force) script += " --force";
  return script + "\n";
}

int submit_slurm(const SweepPlan& plan, const SlurmRequest& request,
                 const std::vector<const PlannedPoint*>& pending) {
  const std::size_t shards = shard_count(plan, request);
  std::set<std::size_t> tasks;
  for (const PlannedPoint* planned : pending) tasks.insert(planned->point.index % shards);
  const std::filesystem::path script_path = request.dir / "slurm" / "sweep.sbatch";
  std::filesystem::create_directories(script_path.parent_path());
  output::AtomicFile file(script_path);
  file.stream() << slurm_script(plan, request, {tasks.begin(), tasks.end()});
  file.commit();
  const std::string command = "sbatch --parsable" + std::string(request.wait ? " --wait" : "") +
                              " " + quoted(script_path.string());
  std::cout << "sweep: submitting " << pending.size() << " points in " << tasks.size() << " of "
            << shards << " array tasks: " << script_path.string() << std::endl;
  std::unique_ptr<FILE, PipeCloser> pipe(popen(command.c_str(), "r"));
  if (!pipe) throw CliError("sweep: cannot run sbatch", kExitFailure);
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe.get())) output += buffer;
  const int status = pclose(pipe.release());
  while (!output.empty() && output.back() == '\n') output.pop_back();
  if (!output.empty()) std::cout << "sweep: slurm job " << output << std::endl;
  if (status == -1 || !WIFEXITED(status) || (WEXITSTATUS(status) != 0 && output.empty()))
    throw CliError("sweep: sbatch failed (is Slurm installed and running? " + command + ")",
                   kExitFailure);
  return WEXITSTATUS(status);
}

}  // namespace impactbench::cli
