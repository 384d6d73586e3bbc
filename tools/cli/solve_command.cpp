// `impactbench solve FILE --solver NAME [--tol T] [--max-iter N] [--option key=value]...
// [--warm-start CSV] [--solution CSV] [--time-limit S] [--progress]`: one problem file, one
// solver. FCLIB HDF5 files (recognised by their signature, whatever their name) are
// friction-contact problems (global ones reduced to local form); anything else is read as the
// plain-text LCP format (solvers/io/lcp_text_file.hpp). Prints status, iterations, residual(s)
// and time; writes the solution only when the solve succeeded; when it did not, says so in one
// line on stderr and exits 1. A faceted-cone answer to a spatial problem (lemke, pgs) is written
// and exits 3 (kExitFacetedOnly) with one line saying so.
#include <unistd.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "lib/output/message_text.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/fclib_file.hpp"
#include "solvers/io/lcp_text_file.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/output_paths.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/cli/solution_csv.hpp"
#include "tools/cli/solve_monitor.hpp"
#include "tools/cli/solve_settings.hpp"

namespace impactbench::cli {
namespace {

/// A solve that counts as done: converged, or (spatial lemke/pgs) the faceted LCP solved.
bool succeeded(const solvers::SolverResult& result) {
  return result.converged() || result.status == solvers::SolverStatus::kConvergedFaceted;
}

class SolveCommand : public Command {
 public:
  explicit SolveCommand(CLI::App* app) : Command(app) {
    app->add_option("file", path_,
                    "Problem file: FCLIB HDF5 (detected by its signature), or the plain-text LCP "
                    "format")
        ->required();
    app->add_option("--solver", solver_,
                    "Solver name (LCP: lemke, pgs, psor, newton-fb, enum; "
                    "friction: prox-jacobi, prox-gs, nsgs, nsn, lemke, pgs)")
        ->required();
    app->add_option("--tol", tolerance_, "Residual tolerance (default: the solver's)")
        ->check(kPositiveFinite);
    app->add_option("--max-iter", max_iterations_, "Iteration limit (default: the solver's)")
        ->check(kPositiveFinite);
    app->add_option("--option", option_entries_,
                    "Solver setting key=value (repeatable): psor relaxation; lemke/pgs "
                    "cone_facets; prox-jacobi/prox-gs omega, rho_scale; nsn rho_scale");
    app->add_option("--warm-start", warm_start_,
                    "Start from a solution CSV as written by --solution");
    app->add_option("--solution", solution_,
                    "Write the solution as CSV (LCP: i,z,w; friction: contact,r_*,u_*)");
    app->add_option("--time-limit", time_limit_,
                    "Stop the solver after this much process CPU time [s]")
        ->check(kPositiveFinite);
    app->footer(
        "Exit status: 0 solved to the tolerance; 1 not solved, or a bad file; 2 usage; 3 (lemke "
        "and pgs on a spatial problem) the faceted-cone LCP was solved and its solution written, "
        "but the Coulomb residual of the problem as stated is above the tolerance.");
    app->add_flag("--progress", progress_,
                  "Progress line on stderr every second of a long solve (default: when stderr "
                  "is a terminal)");
  }

  int run() override {
    std::error_code error;
    if (!std::filesystem::exists(path_, error))
      throw CliError(path_.string() + ": no such file", kExitFailure);
    const bool friction = solvers::is_hdf5_file(path_);  // by signature, not by name
    solvers::SolverOptions options =
        solver_options(solver_, friction, tolerance_, max_iterations_, option_entries_);
    if (solution_) {
      check_output_path(*solution_, "--solution");
      std::vector<std::pair<std::string, std::filesystem::path>> inputs{{"problem", path_}};
      if (warm_start_) inputs.emplace_back("--warm-start", *warm_start_);
      check_outputs_spare_inputs({{"--solution", *solution_}}, inputs);
    }
    if (warm_start_ && !std::filesystem::is_regular_file(*warm_start_, error))
      throw CliError("--warm-start " + warm_start_->string() + ": no such file", kExitFailure);

    SolveMonitor monitor(time_limit_, progress_ || isatty(STDERR_FILENO) == 1);
    options.monitor = [&monitor](int iteration, double residual) {
      return monitor(iteration, residual);
    };

    solvers::SolverResult result;
    SolutionShape shape;
    std::optional<double> reference_residual;
    std::optional<Eigen::VectorXd> start;
    if (friction) {
      const auto file = solvers::read_fclib_file(path_);
      shape = {file.problem.dimension, file.problem.size()};
      if (warm_start_) start = read_warm_start_csv(*warm_start_, shape);
      std::printf("problem  %s: friction contact, %d contacts in %dD%s\n", path_.c_str(),
                  file.problem.num_contacts(), file.problem.dimension,
                  file.title.empty() ? "" : (" (" + file.title + ")").c_str());
      monitor.restart();  // reading the file is not solving it
      result = solvers::solve_friction(file.problem, solver_, options, start ? &*start : nullptr);
      if (file.reference_r)
        reference_residual = solvers::friction_residual(file.problem, *file.reference_r);
    } else {
      const auto problem = solvers::io::read_lcp_file(path_);
      shape = {0, problem.size()};
      if (warm_start_) start = read_warm_start_csv(*warm_start_, shape);
      std::printf("problem  %s: LCP, n = %d (%s)\n", path_.c_str(), problem.size(),
                  problem.is_sparse ? "sparse" : "dense");
      monitor.restart();
      result = solvers::solve_lcp(problem, solver_, options, start ? &*start : nullptr);
    }
    const double cpu_seconds = monitor.cpu_seconds();
    report(options, result, cpu_seconds, monitor, reference_residual);
    if (!succeeded(result))
      throw CliError(solver_ + " did not solve " +
                         output::printable(path_.filename().string(), 80) + " (status " +
                         std::string(solvers::to_string(result.status)) + ")",
                     kExitFailure);
    if (solution_) {
      try {
        write_solution_csv(*solution_, shape, result);
      } catch (const std::exception& failure) {
        throw CliError("--solution " + solution_->string() + ": " + failure.what(), kExitFailure);
      }
    }
    if (result.status == solvers::SolverStatus::kConvergedFaceted) {
      std::fprintf(stderr,
                   "impactbench: %s solved the faceted-cone LCP of %s, not the problem as stated: "
                   "Coulomb residual %s above the tolerance %s (exit %d)\n",
                   solver_.c_str(), output::printable(path_.filename().string(), 80).c_str(),
                   output::number_text(result.residual).c_str(),
                   output::number_text(options.tolerance).c_str(), kExitFacetedOnly);
      return kExitFacetedOnly;
    }
    return 0;
  }

 private:
  void report(const solvers::SolverOptions& options, const solvers::SolverResult& result,
              double cpu_seconds, const SolveMonitor& monitor,
              const std::optional<double>& reference_residual) const {
    std::printf("solver   %s (tol %s, max %d iterations)\n", solver_.c_str(),
                output::number_text(options.tolerance).c_str(), options.max_iterations);
    std::string message = result.message;
    if (monitor.time_limit_reached())
      message = "time limit " + output::number_text(*time_limit_) + " s (process CPU) reached";
    std::printf("status   %s%s%s\n", std::string(solvers::to_string(result.status)).c_str(),
                message.empty() ? "" : ": ", message.c_str());
    std::printf("iterations %d\nresidual %s\n", result.iterations,
                output::number_text(result.residual).c_str());
    if (!std::isnan(result.faceted_residual))
      std::printf("faceted-cone LCP residual %s (natural map ||min(z, Mz + q)||_inf)\n",
                  output::number_text(result.faceted_residual).c_str());
    std::printf("time     %s s wall, %s s process CPU\n",
                output::number_text(result.seconds).c_str(),
                output::number_text(cpu_seconds).c_str());
    if (reference_residual)
      std::printf("file's reference solution: residual %s (same measure)\n",
                  output::number_text(*reference_residual).c_str());
  }

  std::filesystem::path path_;
  std::string solver_;
  std::optional<double> tolerance_;
  std::optional<int> max_iterations_;
  std::vector<std::string> option_entries_;
  std::optional<std::filesystem::path> warm_start_;
  std::optional<std::filesystem::path> solution_;
  std::optional<double> time_limit_;
  bool progress_ = false;
};

}  // namespace

std::unique_ptr<Command> add_solve_command(CLI::App& app) {
  return std::make_unique<SolveCommand>(
      app.add_subcommand("solve", "Solve one LCP or FCLIB friction-contact problem file"));
}

}  // namespace impactbench::cli
