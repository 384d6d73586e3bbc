// Driver for every friction-contact solver: validation, dispatch by name, one residual.
#include "solvers/friction/friction_solvers.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "solvers/common/all_finite.hpp"
#include "solvers/common/number_text.hpp"
#include "solvers/friction/delassus_access.hpp"
#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solver_list.hpp"

namespace impactbench::solvers {

namespace friction_detail {
using SolverFunction = std::function<Outcome(const FrictionProblem&, const SolverOptions&,
                                             CapacityVector&, const SolveEntry&)>;

// A solver that does not start from the driver's entry evaluation.
template <Outcome (*solve)(const FrictionProblem&, const SolverOptions&, CapacityVector&)>
Outcome without_entry(const FrictionProblem& problem, const SolverOptions& options,
                      CapacityVector& r, const SolveEntry&) {
  return solve(problem, options, r);
}

struct RegistryEntry {
  SolverInfo info;
  SolverFunction run;
  bool through_lcp = false;      ///< lemke and pgs: the LCP form (faceted cone in space)
  bool sweeps_factored = false;  ///< nsgs, prox-gs: sweep W = H A without forming it
};

void take_entry_velocity(const FrictionProblem& problem, VectorView r, const SolveEntry& entry,
                         const std::vector<factor_blocks::RigidContactBlocks>* rigid,
                         CapacityVector& velocity) {
  if (entry.factored_velocity != nullptr &&
      entry.factored_velocity->size() == problem.factored_velocities())
    velocity.swap(*entry.factored_velocity);
  else
    write_factored_velocity(problem, r, velocity, rigid);
}

CapacityVector& kept_outcome_velocity() {
  thread_local CapacityVector storage;
  return storage;
}
}  // namespace friction_detail

namespace {

using friction_detail::RegistryEntry;

const std::vector<RegistryEntry>& registry() {
  static const std::vector<RegistryEntry> entries = {
      {{"prox-jacobi", "proximal point B.16/B.17, Jacobi sweeps, adaptive per-contact rho", 1e-10,
        5000, true},
       friction_detail::solve_prox_jacobi},
      {{"prox-gs", "proximal point B.16/B.17, Gauss-Seidel sweeps, adaptive per-contact rho", 1e-10,
        5000, true},
       friction_detail::solve_prox_gauss_seidel,
       false,
       true},
      {{"nsgs", "nonsmooth Gauss-Seidel with exact single-contact solves", 1e-10, 1000, true},
       friction_detail::solve_nonsmooth_gauss_seidel,
       false,
       true},
      {{"nsn", "semismooth Newton on the Alart-Curnier function, line search, NSGS fallback", 1e-10,
        200, true},
       friction_detail::without_entry<friction_detail::solve_semismooth_newton>},
      {{"lemke", "Lemke on the LCP form (exact planar, faceted cone spatial)", 1e-10, 100000,
        false},
       [](const FrictionProblem& p, const SolverOptions& o, CapacityVector& r,
          const friction_detail::SolveEntry&) {
         return friction_detail::solve_through_lcp(p, o, "lemke", r);
       },
       true},
      {{"pgs",
        "projected Gauss-Seidel on the LCP form by contact blocks (exact local pivoting solves)",
        1e-10, 10000, true},
       friction_detail::without_entry<friction_detail::solve_lcp_block_gauss_seidel>,
       true},
  };
  return entries;
}

/// Why a factored problem's factor_blocks do not describe n rows of H over nv velocities, or
/// empty (also when there are none).
std::string factor_blocks_problem(const FactorBlocks& blocks, int contacts, int dimension,
                                  long nv) {
  if (blocks.empty()) return {};
  const std::size_t count = blocks.first_velocity.size();
  if (blocks.contact_start.size() != static_cast<std::size_t>(contacts) + 1 ||
      blocks.contact_start.front() != 0 || blocks.contact_start.back() != static_cast<int>(count) ||
      blocks.size.size() != count || blocks.offset.size() != count)
    return "factor_blocks does not list " + std::to_string(contacts) + " contacts' blocks";
  for (int i = 0; i < contacts; ++i) {
    long end_of_previous = 0;
    for (int b = blocks.contact_start[static_cast<std::size_t>(i)];
         b < blocks.contact_start[static_cast<std::size_t>(i) + 1]; ++b) {
      const auto k = static_cast<std::size_t>(b);
      if (b < 0 || k >= count) return "factor_blocks has contact starts out of order";
      const long first = blocks.first_velocity[k], size = blocks.size[k];
      const long entries = 2L * dimension * size;
      if (first < end_of_previous || size <= 0 || first + size > nv || blocks.offset[k] < 0 ||
          blocks.offset[k] + entries > static_cast<long>(blocks.values.size()))
        return "factor_blocks: block " + std::to_string(b) + " of contact " + std::to_string(i) +
               " lies outside the velocities or the values, or overlaps the one before";
      end_of_previous = first + size;
    }
  }
  return {};
}

/// Why the problem cannot be solved, or empty. Sets `status` accordingly.
std::string validate(const FrictionProblem& problem, const SolverOptions& options,
                     WarmStart warm_start, SolverStatus& status) {
  status = SolverStatus::kInvalidProblem;
  if (problem.dimension != 2 && problem.dimension != 3) {
    return "dimension must be 2 (planar) or 3 (spatial), got " + std::to_string(problem.dimension);
  }
  const long n = problem.q.size();
  if (n != static_cast<long>(problem.dimension) * problem.mu.size()) {
    return "q has " + std::to_string(n) + " entries, expected dimension x contacts = " +
           std::to_string(problem.dimension * problem.mu.size());
  }
  if (problem.is_factored && !problem.factored_by_blocks_only() &&
      (problem.factor_H.rows() != n || problem.factor_A.cols() != n ||
       problem.factor_H.cols() != problem.factor_A.rows())) {
    return "the factors of W are H " + std::to_string(problem.factor_H.rows()) + "x" +
           std::to_string(problem.factor_H.cols()) + " and A " +
           std::to_string(problem.factor_A.rows()) + "x" + std::to_string(problem.factor_A.cols()) +
           ", expected " + std::to_string(n) + "xN and Nx" + std::to_string(n);
  }
  if (problem.is_factored) {
    const FactorBlocks& factor_blocks = problem.factor_blocks;
    if (!factor_blocks.empty() && !problem.factored_by_blocks_only() &&
        factor_blocks.velocities != problem.factor_A.rows())
      return "factor_blocks has " + std::to_string(factor_blocks.velocities) +
             " velocities, A has " + std::to_string(problem.factor_A.rows()) + " rows";
    if (!factor_blocks.empty() && factor_blocks.velocities < 0)
      return "factor_blocks has a negative number of velocities";
    const std::string blocks = factor_blocks_problem(
        factor_blocks, problem.num_contacts(), problem.dimension, problem.factored_velocities());
    if (!blocks.empty()) return blocks;
  }
  const long rows = problem.is_sparse ? problem.sparse_W.rows() : problem.dense_W.rows();
  const long cols = problem.is_sparse ? problem.sparse_W.cols() : problem.dense_W.cols();
  if (!problem.is_factored && (rows != n || cols != n)) {
    return "W is " + std::to_string(rows) + "x" + std::to_string(cols) + ", expected " +
           std::to_string(n) + "x" + std::to_string(n);
  }
  if (warm_start != nullptr && warm_start->size() != n) {
    return "warm start has " + std::to_string(warm_start->size()) + " entries, expected " +
           std::to_string(n);
  }
  if (!(options.tolerance >= 0.0) || options.max_iterations < 0) {
    return "tolerance must be >= 0 and max_iterations >= 0";
  }
  status = SolverStatus::kNonFiniteData;
  const auto finite_values = [](const auto& sparse) {
    return all_finite(sparse.valuePtr(), sparse.nonZeros());
  };
  const bool w_finite =
      problem.is_factored
          ? finite_values(problem.factor_H) && finite_values(problem.factor_A) &&
                all_finite(problem.factor_blocks.values.data(),
                           static_cast<Eigen::Index>(problem.factor_blocks.values.size()))
      : problem.is_sparse ? finite_values(problem.sparse_W)
                          : all_finite(problem.dense_W);
  if (!w_finite) return "W contains NaN or Inf";
  if (!all_finite(problem.q)) return "q contains NaN or Inf";
  if (!all_finite(problem.mu)) return "mu contains NaN or Inf";
  if (warm_start != nullptr && !all_finite(*warm_start)) return "warm start contains NaN or Inf";
  status = SolverStatus::kInvalidProblem;
  for (int i = 0; i < problem.num_contacts(); ++i) {
    if (problem.mu(i) < 0.0) {
      return "friction coefficient mu of contact " + std::to_string(i) + " is negative (" +
             output::number_text(problem.mu(i)) + ")";
    }
  }
  if (problem.dimension == 3 && options.cone_facets < 3) {
    return "cone_facets must be >= 3, got " + std::to_string(options.cone_facets);
  }
  return {};
}

}  // namespace

const std::vector<SolverInfo>& friction_solvers() {
  static const std::vector<SolverInfo> infos = [] {
    std::vector<SolverInfo> list;
    for (const RegistryEntry& entry : registry()) list.push_back(entry.info);
    return list;
  }();
  return infos;
}

FrictionSolver::FrictionSolver(std::string_view name) : entry_(nullptr) {
  for (const RegistryEntry& candidate : registry()) {
    if (candidate.info.name == name) entry_ = &candidate;
  }
  if (entry_ == nullptr) {
    std::string names;
    for (const RegistryEntry& candidate : registry()) names += " " + candidate.info.name;
    throw std::invalid_argument("unknown friction solver '" + std::string(name) +
                                "'; known:" + names);
  }
}

const SolverInfo& FrictionSolver::info() const {
  return entry_->info;
}
bool FrictionSolver::solves_through_lcp() const {
  return entry_->through_lcp;
}
bool FrictionSolver::sweeps_factored_delassus() const {
  return entry_->sweeps_factored;
}

SolverResult solve_friction(const FrictionProblem& problem, std::string_view solver,
                            const SolverOptions& options, WarmStart warm_start) {
  return FrictionSolver(solver).solve(problem, options, warm_start);
}

SolverResult FrictionSolver::solve(const FrictionProblem& problem, const SolverOptions& options,
                                   WarmStart warm_start) const {
  SolverResult result;
  solve(problem, options, warm_start, result);
  return result;
}

void FrictionSolver::solve(const FrictionProblem& problem, const SolverOptions& options,
                           WarmStart warm_start, SolverResult& result) const {
  result.iterations = 0;
  result.residual = 0.0;
  result.faceted_residual = std::numeric_limits<double>::quiet_NaN();
  result.seconds = 0.0;
  result.status = SolverStatus::kInvalidProblem;
  result.message.clear();
  if (std::string reason = validate(problem, options, warm_start, result.status); !reason.empty()) {
    result.message = std::move(reason);
    result.solution.resize(0);
    result.velocity.resize(0);
    result.factored_velocity.resize(0);
    return;
  }
  if (problem.is_factored && !sweeps_factored_delassus()) {
    result = solve(formed_delassus(problem), options, warm_start);
    return;
  }
  const auto start = options.measure_seconds ? std::chrono::steady_clock::now()
                                             : std::chrono::steady_clock::time_point{};
  CapacityVector& r = result.solution;
  if (warm_start != nullptr)
    r = *warm_start;
  else
    r.setZero(problem.size());
  friction_detail::Outcome outcome;
  // Trivial case (also q = 0 or a warm start that already solves the problem): no iteration.
  // A factored problem's A r at the entry is kept for a solver that starts from it.
  thread_local CapacityVector entry_factored_velocity;
  friction_detail::SolveEntry entry;
  // A r at the answer, when it is formed there afresh. Its storage is reserved by every solve
  // of a factored problem, so that a caller solving into a kept result allocates nothing for
  // it once it has solved its largest problem, whichever way that solve ended.
  result.factored_velocity.resize(0);
  if (problem.is_factored) {
    result.factored_velocity.reserve(problem.factored_velocities());
    entry.factored_velocity = &entry_factored_velocity;
    entry.answer_factored_velocity = &result.factored_velocity;
  }
  write_contact_velocity(problem, r, result.velocity, entry.factored_velocity);
  bool velocity_at_r = true;  // result.velocity is u at the final r
  entry.residual = friction_residual(problem, r, result.velocity);
  if (entry.residual <= options.tolerance) {
    outcome.status = SolverStatus::kConverged;
    outcome.residual = entry.residual;
    if (problem.is_factored) result.factored_velocity = entry_factored_velocity;  // at this r
  } else {
    // The entry's u is not needed any more: its storage goes to the solver's Outcome.
    result.velocity.swap(friction_detail::kept_outcome_velocity());
    outcome = entry_->run(problem, options, r, entry);
    // u at the final r: the solver's own when it evaluated it there, else one product with W.
    velocity_at_r = outcome.velocity.size() == problem.size();
    if (velocity_at_r) result.velocity.swap(outcome.velocity);
    // The storage left over is kept for the next solve: the entry's u when the solver took none.
    CapacityVector& kept = friction_detail::kept_outcome_velocity();
    if (kept.size() == 0) kept.swap(outcome.velocity);
  }
  result.seconds =
      options.measure_seconds
          ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
          : std::numeric_limits<double>::quiet_NaN();
  // u formed here goes through A r at the final r, which a factored problem's result keeps (its
  // storage reserved above): a time stepper then adds it instead of forming it again.
  if (!velocity_at_r)
    write_contact_velocity(problem, r, result.velocity,
                           problem.is_factored ? &result.factored_velocity : nullptr);
  result.residual = velocity_at_r && !std::isnan(outcome.residual)
                        ? outcome.residual
                        : friction_residual(problem, r, result.velocity);
  result.iterations = outcome.iterations;
  result.message = std::move(outcome.message);
  result.faceted_residual = outcome.faceted_residual;
  const bool small = result.residual <= options.tolerance;  // NaN compares false
  const bool ordinary_stop = outcome.status == SolverStatus::kConverged ||
                             outcome.status == SolverStatus::kMaxIterations ||
                             outcome.status == SolverStatus::kStalled ||
                             outcome.status == SolverStatus::kStopped;
  if (small && ordinary_stop) {
    result.status = SolverStatus::kConverged;
  } else if (outcome.status == SolverStatus::kConverged &&
             result.faceted_residual <= options.tolerance) {
    // The faceted cone's LCP was solved: its answer, not a failure of the solver.
    result.status = SolverStatus::kConvergedFaceted;
    result.message = "solved the faceted-cone LCP (residual " +
                     output::number_text(result.faceted_residual) + "); Coulomb residual " +
                     output::number_text(result.residual) + " above tolerance" +
                     (result.message.empty() ? "" : "; " + result.message);
  } else if (outcome.status == SolverStatus::kConverged) {
    result.status = SolverStatus::kStalled;
    result.message = "friction residual " + output::number_text(result.residual) +
                     " above tolerance" + (result.message.empty() ? "" : "; " + result.message);
  } else {
    result.status = outcome.status;
  }
}

}  // namespace impactbench::solvers
