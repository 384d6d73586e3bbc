#pragma once
// The `--option key=value` settings of `impactbench solve`: which keys each solver reads
// (psor's relaxation, the cone facets of the LCP conversions, ω and ρ of the proximal and Newton
// solvers), how each is read and checked, and the message listing the keys a solver accepts.
#include <optional>
#include <string>
#include <vector>

#include "solvers/common/solver_types.hpp"

namespace impactbench::cli {

/// Sets the entries on `options`; throws CliError (usage) for a malformed entry, a key that
/// `solver` does not read (naming the keys it does) or a value outside its range.
void apply_solver_settings(const std::vector<std::string>& entries, const std::string& solver,
                           bool friction, solvers::SolverOptions& options);

/// The options of a solve as `impactbench solve` sets them: the named solver of the kind
/// (friction or LCP; else CliError (usage) listing that kind's solvers), its default tolerance
/// and iteration limit unless given, then the --option entries (apply_solver_settings).
solvers::SolverOptions solver_options(const std::string& solver, bool friction,
                                      std::optional<double> tolerance,
                                      std::optional<int> max_iterations,
                                      const std::vector<std::string>& entries);

/// "key (accepts)" for each key `solver` reads, for `--help` and messages; empty if none.
std::string solver_setting_keys(const std::string& solver, bool friction);

}  // namespace impactbench::cli
