// Optional comparison with Siconos Numerics (built only when libsiconos-numerics-dev is found):
// each benchmark solves the very same problem with one of our solvers and with the
// corresponding Siconos solver, at the same tolerance and iteration limit, from r = 0 (z = 0).
// Names: siconos/<our solver>/<problem>/<contacts or file stem>; siconos/lemke/siconos_lcp/<file>
// for Siconos' own LCP test problems (share/impactbench/lcp_siconos).
//   LCP (lcp_bench's families and options): lemke ↔ lcp_lexicolemke, pgs ↔ lcp_pgs,
//     newton-fb ↔ lcp_newton_FB (FBLSA). Siconos' LCP solvers take dense M only, so the sparse
//     family is handed to Siconos as a dense copy. No psor pair: Siconos 4.4's lcp_psor prints
//     "omega is not used" and runs plain PGS.
//   Friction contact (friction_bench's spatial piles and the FCLIB files): nsgs ↔ fc3d NSGS,
//     nsn ↔ fc3d NSN_AC (Alart–Curnier), prox-gs ↔ fc3d PROX (proximal point; Siconos solves
//     each proximal step with NSN_AC, ours with a Gauss–Seidel sweep), W in Siconos'
//     sparse-block storage.
// Both solutions are measured with OUR residual (natural map ‖min(z, w)‖∞ for LCP; the FCLIB
// measure ‖r − Π_K(r − (u + g(u)))‖ / ‖q‖ for friction contact), and "converged" means that
// residual ≤ tolerance for either code. Siconos stops on its own measures: for LCP
// ‖z − Π(z − w)‖₂ / ‖q‖, for fc3d the same numerator as ours divided by max(‖q‖, ‖r‖) (checked:
// ours × ‖q‖ / max(‖q‖, ‖r‖) reproduces its reported error to all digits), which on piles with
// ‖r‖ ≫ ‖q‖ stops 20–80× short of our tolerance. So Siconos' tolerance is calibrated (untimed):
// solved at our tolerance, then, while our measure of its answer is above it, re-solved with
// its tolerance scaled by ½ · ours-tolerance / our-residual (at most 4 times); the timed solves
// use the final value (counter siconos_tolerance). Siconos' own final error is reported as
// siconos_own_error. Times are CPU seconds per solve, timed over as many solves in a row as
// span 1 ms (seconds_per_solve) and averaged over repeated calls; time_ratio = ours / Siconos.
// Both sides solve into storage kept across the solves: Siconos' driver into the caller's arrays,
// ours into one SolverResult (solve_lcp's and FrictionSolver::solve's kept-result forms), with
// the driver's own timer off (SolverOptions::measure_seconds). Run
// with OPENBLAS_NUM_THREADS=1 (tools/siconos_comparison.py does) so that Siconos' BLAS calls are
// single-threaded like our code.
#include <algorithm>
#include <cmath>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "Friction_cst.h"
#include "common/fclib_collection.hpp"
#include "common/friction_bench_run.hpp"
#include "common/friction_piles.hpp"
#include "common/lcp_bench_families.hpp"
#include "common/registered_main.hpp"
#include "lcp_cst.h"
#include "lib/resources/resource_paths.hpp"
#include "siconos/siconos_numerics.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/lcp_text_file.hpp"
#include "solvers/lcp/lcp_residual.hpp"
#include "solvers/lcp/lcp_solvers.hpp"

namespace {

using impactbench::bench::SiconosRun;
namespace solvers = impactbench::solvers;

/// CPU seconds per solve. `timed(repeats)` runs `repeats` solves in a row and returns their
/// CPU time per solve; the process clock ticks in microseconds, so the repeats grow tenfold
/// until one call lasts 1 ms (a tick is then under 0.1 % of it). Calls are then repeated until
/// 0.2 s have been spent or 100 calls made, and their mean is returned. `repeats` is in and out:
/// the count found for our solver is where the Siconos side starts.
double seconds_per_solve(const std::function<double(int)>& timed, int& repeats) {
  double seconds = timed(repeats);
  while (seconds * repeats < 1e-3 && repeats < 1000000) {
    repeats *= 10;
    seconds = timed(repeats);
  }
  double total = seconds * repeats;
  double solves = repeats;
  int calls = 1;
  while (total < 0.2 && calls < 100) {
    total += timed(repeats) * repeats;
    solves += repeats;
    ++calls;
  }
  return total / solves;
}

double cpu_seconds_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

/// Siconos' tolerance giving our measure ≤ `tolerance` on its answer (see the header comment):
/// `solve(t)` runs Siconos at tolerance t and returns our residual of its answer, NaN when
/// Siconos itself reports failure (then the last tolerance it met is kept).
double calibrated_tolerance(double tolerance, const std::function<double(double)>& solve) {
  double met = tolerance;  // the last tolerance Siconos reported reaching
  double trial = tolerance;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const double ours = solve(trial);
    if (std::isnan(ours)) return met;
    met = trial;
    if (ours <= tolerance) break;
    trial *= 0.5 * tolerance / ours;
  }
  return met;
}

struct Side {
  int iterations = 0;
  double residual = 0.0;
  bool converged = false;
  double seconds = 0.0;
  Eigen::VectorXd solution;
  double tolerance = 0.0;
};

void report(benchmark::State& state, int contacts, const Side& ours, const Side& theirs,
            const SiconosRun& siconos, const std::string& siconos_name) {
  state.counters["contacts"] = contacts;
  state.counters["ours_iterations"] = ours.iterations;
  state.counters["ours_residual"] = ours.residual;
  state.counters["ours_converged"] = ours.converged ? 1.0 : 0.0;
  state.counters["ours_seconds"] = ours.seconds;
  state.counters["siconos_iterations"] = theirs.iterations;
  state.counters["siconos_residual"] = theirs.residual;
  state.counters["siconos_own_error"] = siconos.own_error;
  state.counters["siconos_info"] = siconos.info;
  state.counters["siconos_converged"] = theirs.converged ? 1.0 : 0.0;
  state.counters["siconos_seconds"] = theirs.seconds;
  state.counters["siconos_tolerance"] = theirs.tolerance;
  state.counters["time_ratio"] = theirs.seconds > 0.0 ? ours.seconds / theirs.seconds : 0.0;
  // How far apart the two answers are (both may be solutions when the problem's is not unique).
  const double scale = std::max(1e-300, ours.solution.norm());
  state.counters["solution_difference"] = (ours.solution - theirs.solution).norm() / scale;
  state.SetLabel(siconos_name);
}

/// One comparison: `solve_ours(result)` runs our solver into a result kept across solves (as
/// Siconos' driver writes into the z and w arrays it is handed), `solve_siconos(t, k)` the
/// Siconos one at tolerance t, k times in a row, `measure(x)` is our residual of a solution x.
void compare(benchmark::State& state, int contacts, double tolerance,
             const std::function<void(solvers::SolverResult&)>& solve_ours,
             const std::function<SiconosRun(double, int)>& solve_siconos,
             const std::function<double(const Eigen::VectorXd&)>& measure,
             const std::string& siconos_name) {
  const double siconos_tolerance = calibrated_tolerance(tolerance, [&](double t) {
    const SiconosRun run = solve_siconos(t, 1);
    return run.info == 0 ? measure(run.solution) : std::nan("");
  });
  Side ours;
  Side theirs;
  SiconosRun siconos;
  for (auto _ : state) {
    solvers::SolverResult result;
    int repeats = 1;
    ours.seconds = seconds_per_solve(
        [&](int k) {
          const std::clock_t start = std::clock();
          for (int call = 0; call < k; ++call) solve_ours(result);
          return cpu_seconds_since(start) / k;
        },
        repeats);
    theirs.seconds = seconds_per_solve(
        [&](int k) {
          siconos = solve_siconos(siconos_tolerance, k);
          return siconos.seconds;
        },
        repeats);
    ours = {result.iterations, result.residual, result.converged(),
            ours.seconds,      result.solution, tolerance};
  }
  const double residual = measure(siconos.solution);
  theirs = {siconos.iterations, residual,         residual <= tolerance,
            theirs.seconds,     siconos.solution, siconos_tolerance};
  report(state, contacts, ours, theirs, siconos, siconos_name);
}

void compare_lcp(benchmark::State& state, const std::string& solver, int siconos_id,
                 const solvers::LcpProblem& problem, const solvers::SolverOptions& options) {
  compare(
      state, problem.size(), options.tolerance,
      [&](solvers::SolverResult& result) {
        solvers::solve_lcp(problem, solver, options, nullptr, result);
      },
      [&](double t, int repeats) {
        return impactbench::bench::siconos_lcp(problem, siconos_id, t, options.max_iterations,
                                               repeats);
      },
      [&](const Eigen::VectorXd& z) {
        return solvers::lcp::natural_map_residual(z, solvers::lcp::lcp_velocity(problem, z));
      },
      impactbench::bench::siconos_solver_name(siconos_id));
}

void compare_friction(benchmark::State& state, const std::string& solver, int siconos_id,
                      const solvers::FrictionProblem& problem) {
  const solvers::SolverOptions options = impactbench::bench::friction_bench_options(solver);
  compare(
      state, problem.num_contacts(), options.tolerance,
      [&, ours = solvers::FrictionSolver(solver)](solvers::SolverResult& result) {
        ours.solve(problem, options, nullptr, result);
      },
      [&](double t, int repeats) {
        return impactbench::bench::siconos_fc3d(problem, siconos_id, t, options.max_iterations,
                                                repeats);
      },
      [&](const Eigen::VectorXd& r) { return solvers::friction_residual(problem, r); },
      impactbench::bench::siconos_solver_name(siconos_id));
}

void add(const std::string& name, std::function<void(benchmark::State&)> run) {
  benchmark::RegisterBenchmark(name.c_str(), std::move(run))
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond);
}

void register_all() {
  struct Pair {
    std::string ours;
    int siconos;
  };
  const std::vector<Pair> lcp_pairs = {{"lemke", SICONOS_LCP_LEMKE},
                                       {"pgs", SICONOS_LCP_PGS},
                                       {"newton-fb", SICONOS_LCP_NEWTON_FB_FBLSA}};
  for (const Pair& pair : lcp_pairs) {
    for (const std::string family : {"spd_dense", "contact_sparse"}) {
      for (const int n : {10, 100, 1000}) {
        add("siconos/" + pair.ours + "/" + family + "/" + std::to_string(n),
            [pair, family, n](benchmark::State& state) {
              compare_lcp(state, pair.ours, pair.siconos,
                          impactbench::bench::lcp_family_problem(family, n),
                          impactbench::bench::lcp_bench_options(pair.ours, family, n));
            });
      }
    }
  }
  // Siconos' own LCP test problems (share/impactbench/lcp_siconos), Lemke against its LEMKE.
  for (const auto& path : impactbench::bench::collection_files(
           impactbench::resources::lcp_collection_directory(), ".lcp")) {
    add("siconos/lemke/siconos_lcp/" + path.stem().string(), [path](benchmark::State& state) {
      const solvers::LcpProblem problem = solvers::io::read_lcp_file(path);
      compare_lcp(state, "lemke", SICONOS_LCP_LEMKE, problem,
                  impactbench::bench::lcp_bench_options("lemke", "siconos_lcp", problem.size()));
    });
  }
  const std::vector<Pair> friction_pairs = {{"nsgs", SICONOS_FRICTION_3D_NSGS},
                                            {"nsn", SICONOS_FRICTION_3D_NSN_AC},
                                            {"prox-gs", SICONOS_FRICTION_3D_PROX}};
  for (const Pair& pair : friction_pairs) {
    for (const int contacts : {100, 1000, 10000}) {
      // As in friction_bench: the Newton methods factor a 3n system per step.
      if (pair.ours == "nsn" && contacts > 3000) continue;
      add("siconos/" + pair.ours + "/spatial_pile/" + std::to_string(contacts),
          [pair, contacts](benchmark::State& state) {
            compare_friction(state, pair.ours, pair.siconos,
                             impactbench::bench::cached_pile_problem(3, contacts));
          });
    }
    for (const auto& path :
         impactbench::bench::fclib_collection_files(impactbench::resources::fclib_directory())) {
      add("siconos/" + pair.ours + "/fclib/" + path.stem().string(),
          [pair, path](benchmark::State& state) {
            compare_friction(state, pair.ours, pair.siconos,
                             impactbench::bench::cached_fclib_problem(path).problem);
          });
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  return impactbench::bench::run_registered_benchmarks(argc, argv, register_all);
}
