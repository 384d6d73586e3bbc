// `impactbench solve FILE --solver NAME [--tol T] [--max-iter N]`: one problem file, one
// solver. FCLIB HDF5 files (recognised by their signature) are friction-contact problems (global
// ones reduced to local form); anything else is read as the plain-text LCP format
// (solvers/io/lcp_text_file.hpp). Prints status, iterations, residual and time; exits 1 when the
// solver did not converge.
#include <cstdio>
#include <optional>
#include <string>

#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/fclib_file.hpp"
#include "solvers/io/lcp_text_file.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/setting_flags.hpp"

namespace impactbench::cli {
namespace {

const solvers::SolverInfo& find_solver(const std::vector<solvers::SolverInfo>& registry,
                                       const std::string& name, const char* kind) {
  std::string names;
  for (const auto& info : registry) {
    if (info.name == name) return info;
    names += (names.empty() ? "" : ", ") + info.name;
  }
  throw CliError(
      std::string("--solver '") + name + "' is not a " + kind + " solver (" + names + ")",
      kExitUsage);
}

class SolveCommand : public Command {
 public:
  explicit SolveCommand(CLI::App* app) : Command(app) {
    app->add_option("file", path_, "Problem file: FCLIB .hdf5/.h5, or the plain-text LCP format")
        ->required();
    app->add_option("--solver", solver_,
                    "Solver name (LCP: lemke, pgs, psor, newton-fb, enum; "
                    "friction: prox-jacobi, prox-gs, nsgs, nsn, lemke, pgs)")
        ->required();
    app->add_option("--tol", tolerance_, "Residual tolerance (default: the solver's)")
        ->check(kPositiveFinite);
    app->add_option("--max-iter", max_iterations_, "Iteration limit (default: the solver's)")
        ->check(kPositiveFinite);
  }

  int run() override {
    if (!std::filesystem::exists(path_))
      throw CliError(path_.string() + ": no such file", kExitFailure);
    const bool friction = solvers::is_hdf5_file(path_);  // by signature, not by name
    const auto& info = find_solver(friction ? solvers::friction_solvers() : solvers::lcp_solvers(),
                                   solver_, friction ? "friction-contact" : "LCP");
    solvers::SolverOptions options;
    options.tolerance = tolerance_.value_or(info.default_tolerance);
    options.max_iterations = max_iterations_.value_or(info.default_max_iterations);

    solvers::SolverResult result;
    std::optional<double> reference_residual;
    if (friction) {
      const auto file = solvers::read_fclib_file(path_);
      std::printf("problem  %s: friction contact, %d contacts in %dD%s\n", path_.c_str(),
                  file.problem.num_contacts(), file.problem.dimension,
                  file.title.empty() ? "" : (" (" + file.title + ")").c_str());
      result = solvers::solve_friction(file.problem, solver_, options);
      if (file.reference_r)
        reference_residual = solvers::friction_residual(file.problem, *file.reference_r);
    } else {
      const auto problem = solvers::io::read_lcp_file(path_);
      std::printf("problem  %s: LCP, n = %d (%s)\n", path_.c_str(), problem.size(),
                  problem.is_sparse ? "sparse" : "dense");
      result = solvers::solve_lcp(problem, solver_, options);
    }
    std::printf("solver   %s (tol %.3g, max %d iterations)\n", solver_.c_str(), options.tolerance,
                options.max_iterations);
    std::printf("status   %s%s%s\n", std::string(solvers::to_string(result.status)).c_str(),
                result.message.empty() ? "" : ": ", result.message.c_str());
    std::printf("iterations %d\nresidual %.6g\ntime     %.6g s\n", result.iterations,
                result.residual, result.seconds);
    if (reference_residual)
      std::printf("file's reference solution: residual %.6g (same measure)\n", *reference_residual);
    return result.converged() ? 0 : kExitFailure;
  }

 private:
  std::filesystem::path path_;
  std::string solver_;
  std::optional<double> tolerance_;
  std::optional<int> max_iterations_;
};

}  // namespace

std::unique_ptr<Command> add_solve_command(CLI::App& app) {
  return std::make_unique<SolveCommand>(
      app.add_subcommand("solve", "Solve one LCP or FCLIB friction-contact problem file"));
}

}  // namespace impactbench::cli
