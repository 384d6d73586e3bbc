// `impactbench sweep SPEC --out DIR [--executor local|slurm] [--jobs N] [--time-limit S]
//  [--merge] [--force] ...`: a campaign of points (sweep_spec.hpp, docs/sweeps.md), each run
// as `compare --engines ENGINE` runs it and kept as one result file in DIR/points/; the points
// whose result is there with the same hash are skipped. `impactbench merge SPEC --out DIR`
// gathers the results into one CSV. The hidden `sweep-point` runs one point by hand, as a worker
// of the pool does.
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>

#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/progress_line.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/cli/sweep_command.hpp"
#include "tools/cli/sweep_local.hpp"
#include "tools/cli/sweep_merge.hpp"
#include "tools/cli/sweep_plan.hpp"
#include "tools/cli/sweep_pool.hpp"
#include "tools/cli/sweep_prepared_point.hpp"
#include "tools/cli/sweep_slurm.hpp"

namespace impactbench::cli {
namespace {

namespace fs = std::filesystem;

/// Prints what the merge wrote and lists the missing points; the exit code.
int report_merge(const SweepPlan& plan, const fs::path& dir, const fs::path& csv) {
  const MergeOutcome merged = merge_sweep(plan, dir, csv);
  std::cout << "sweep: merged " << merged.rows << " of " << plan.points.size() << " points into "
            << csv.string() << "\n";
  if (merged.missing.empty()) return 0;
  std::cerr << "sweep: " << merged.missing.size() << " points have no result:\n";
  for (const PlannedPoint* planned : merged.missing)
    std::cerr << "  " << planned->point.id << "  " << planned->point.definition() << "\n";
  return kExitFailure;
}

std::size_t parse_shard(const std::string& text, std::size_t& shards) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      const unsigned long k = std::stoul(text.substr(0, slash));
      shards = std::stoul(text.substr(slash + 1));
      if (k < shards) return k;
    }
  } catch (const std::exception&) {
  }
  throw CliError("sweep: --shard needs K/N with 0 <= K < N, not '" + text + "'", kExitUsage);
}

class SweepCommand : public Command {
 public:
  explicit SweepCommand(CLI::App* app) : Command(app) {
    app->add_option("spec", spec_, "Sweep file (TOML; docs/sweeps.md)")->required();
    app->add_option("--out", dir_, "Output folder: results, lock, merged CSV")->required();
    app->add_option("--executor", executor_, "local (default: worker processes) or slurm")
        ->check(CLI::IsMember({"local", "slurm"}));
    app->add_option("--jobs", jobs_, "Worker processes (default: the machine's cores)")
        ->check(CLI::Range(1u, 4096u));
    app->add_option("--time-limit", time_limit_,
                    "Wall time per point [s]; a point past it is a result 'timeout' "
                    "(default: the spec's time_limit, else none)")
        ->check(kPositiveFinite);
    app->add_flag("--force", force_, "Run a sweep of more than 100000 points");
    app->add_flag("--progress", progress_,
                  "Show the progress line (default: only when stderr is a terminal)");
    app->add_flag("--merge", merge_, "Merge the results into DIR/sweep.csv at the end");
    app->add_option("--shard", shard_, "Run shard K of N only (K/N; the Slurm array tasks)");
    app->add_flag("--wait", slurm_.wait, "slurm: wait for the job to end, then merge");
    app->add_option("--shards", slurm_.shards, "slurm: array tasks (default: one per 10 points)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}));
    app->add_option("--concurrency", slurm_.concurrency,
                    "slurm: array tasks running at once (%N; default: the spec's, else no limit)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}));
    app->add_option("--slurm-time", slurm_.time, "slurm: --time of each array task");
    app->add_option("--slurm-mem", slurm_.mem, "slurm: --mem of each array task");
    app->add_option("--partition", slurm_.partition, "slurm: partition");
  }

  int run() override {
    const SweepPlan plan = plan_sweep(spec_, force_);
    fs::create_directories(dir_);
    const double time_limit = time_limit_.value_or(plan.spec.time_limit);
    if (executor_ == "slurm" && !shard_) return run_slurm(plan, time_limit);
    std::size_t shards = 0;
    const std::size_t shard = shard_ ? parse_shard(*shard_, shards) : 0;
    PoolOptions options;
    options.dir = dir_;
    options.jobs = jobs_ ? jobs_ : default_sweep_jobs();
    options.time_limit = time_limit;
    options.progress = progress_ || ProgressLine::stderr_is_terminal();
    const LocalSweepOutcome local = run_local_sweep(
        plan, options, [](const std::string& note) { std::cerr << "sweep: " << note << "\n"; },
        shard, shards);
    const PoolOutcome& outcome = local.pool;
    std::cout << "sweep: " << outcome.ran << " points ran (" << outcome.failed
              << " failed or timed out), " << local.already_done << " already done"
              << (outcome.lost ? ", " + std::to_string(outcome.lost) + " lost" : "")
              << "; results in " << (dir_ / "points").string() << "\n";
    if (outcome.interrupted) {
      std::cerr << "sweep: interrupted; run the same command again to finish\n";
      return 130;
    }
    if (outcome.lost) return kExitFailure;
    if (merge_) {
      return report_merge(plan, dir_, dir_ / "sweep.csv");
    }
    return 0;
  }

 private:
  int run_slurm(const SweepPlan& plan, double time_limit) {
    std::vector<std::string> notes;
    const auto pending = pending_points(plan, dir_, notes);
    for (const std::string& note : notes) std::cerr << "sweep: " << note << "\n";
    if (!pending.empty()) {
      slurm_.spec = fs::absolute(spec_);
      slurm_.dir = fs::absolute(dir_);
      slurm_.time_limit = time_limit;
      slurm_.force = force_;
      const int status = submit_slurm(plan, slurm_, pending);
      if (!slurm_.wait) return status;
      remove_empty_work_folders(dir_);  // the array's shards, which share them, have ended
    } else {
      std::cout << "sweep: every point has its result; nothing to submit\n";
    }
    return slurm_.wait || merge_ ? report_merge(plan, dir_, dir_ / "sweep.csv") : 0;
  }

  fs::path spec_;
  fs::path dir_;
  std::string executor_ = "local";
  unsigned jobs_ = 0;
  std::optional<double> time_limit_;
  bool force_ = false;
  bool progress_ = false;
  bool merge_ = false;
  std::optional<std::string> shard_;
  SlurmRequest slurm_;
};

class MergeCommand : public Command {
 public:
  explicit MergeCommand(CLI::App* app) : Command(app) {
    app->add_option("spec", spec_, "Sweep file (TOML; docs/sweeps.md)")->required();
    app->add_option("--out", dir_, "The sweep's output folder")->required();
    app->add_option("--csv", csv_, "CSV to write (default: DIR/sweep.csv)");
    app->add_flag("--force", force_, "The sweep has more than 100000 points");
  }

  int run() override {
    const SweepPlan plan = plan_sweep(spec_, force_);
    return report_merge(plan, dir_, csv_.empty() ? dir_ / "sweep.csv" : csv_);
  }

 private:
  fs::path spec_, dir_, csv_;
  bool force_ = false;
};

class SweepPointCommand : public Command {
 public:
  explicit SweepPointCommand(CLI::App* app) : Command(app) {
    app->add_option("spec", spec_)->required();
    app->add_option("--out", dir_)->required();
    app->add_option("--id", id_)->required();
  }

  int run() override {
    run_sweep_point(spec_, dir_, id_);
    return 0;
  }

 private:
  fs::path spec_, dir_;
  std::string id_;
};

}  // namespace

std::unique_ptr<Command> add_sweep_command(CLI::App& app) {
  return std::make_unique<SweepCommand>(app.add_subcommand(
      "sweep", "Run a sweep of scenarios x engines x settings on every core or a Slurm cluster"));
}

std::unique_ptr<Command> add_merge_command(CLI::App& app) {
  return std::make_unique<MergeCommand>(
      app.add_subcommand("merge", "Merge a sweep's results into one CSV"));
}

std::unique_ptr<Command> add_sweep_point_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("sweep-point", "Run one point of a sweep, as its workers do");
  command->group("");
  return std::make_unique<SweepPointCommand>(command);
}

}  // namespace impactbench::cli
