#include "tools/cli/solve_settings.hpp"

#include <algorithm>
#include <limits>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/output/message_text.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/setting_flags.hpp"

namespace impactbench::cli {
namespace {

using Field = engines::SettingField<solvers::SolverOptions>;
using solvers::SolverOptions;

struct SolverSetting {
  Field field;
  bool friction;                     ///< a key of the friction solvers (else of the LCP ones)
  std::vector<std::string> solvers;  ///< the solvers of that kind that read it
};

const std::vector<SolverSetting>& settings() {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  static const std::vector<SolverSetting> table = {
      {engines::number_field("relaxation", &SolverOptions::relaxation, {0.0, 2.0, true, true}),
       false,
       {"psor"}},
      {engines::whole_field("cone_facets", &SolverOptions::cone_facets, 3, 64),
       true,
       {"lemke", "pgs"}},
      {engines::number_field("omega", &SolverOptions::proximal_omega, {0.0, 1.9, true, false}),
       true,
       {"prox-jacobi", "prox-gs"}},
      {engines::number_field("rho_scale", &SolverOptions::rho_scale, {0.0, kInfinity, true, true}),
       true,
       {"prox-jacobi", "prox-gs", "nsn"}},
  };
  return table;
}

std::vector<const Field*> fields_of(const std::string& solver, bool friction) {
  std::vector<const Field*> fields;
  for (const SolverSetting& setting : settings())
    if (setting.friction == friction &&
        std::find(setting.solvers.begin(), setting.solvers.end(), solver) != setting.solvers.end())
      fields.push_back(&setting.field);
  return fields;
}

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

}  // namespace

solvers::SolverOptions solver_options(const std::string& solver, bool friction,
                                      std::optional<double> tolerance,
                                      std::optional<int> max_iterations,
                                      const std::vector<std::string>& entries) {
  const auto& info = find_solver(friction ? solvers::friction_solvers() : solvers::lcp_solvers(),
                                 solver, friction ? "friction-contact" : "LCP");
  solvers::SolverOptions options;
  options.tolerance = tolerance.value_or(info.default_tolerance);
  options.max_iterations = max_iterations.value_or(info.default_max_iterations);
  apply_solver_settings(entries, solver, friction, options);
  return options;
}

std::string solver_setting_keys(const std::string& solver, bool friction) {
  std::string keys;
  for (const Field* field : fields_of(solver, friction))
    keys += (keys.empty() ? "" : "; ") + field->key + " (" + field->accepts + ")";
  return keys;
}

void apply_solver_settings(const std::vector<std::string>& entries, const std::string& solver,
                           bool friction, solvers::SolverOptions& options) {
  const std::vector<const Field*> fields = fields_of(solver, friction);
  for (const OptionEntry& entry : parse_option_entries(entries)) {
    const std::string key = output::printable(entry.key, 60);
    if (!entry.engine.empty())
      throw CliError("--option " + entry.engine + "." + key +
                         ": solve takes bare key=value settings of its solver",
                     kExitUsage);
    const auto field = std::find_if(fields.begin(), fields.end(),
                                    [&](const Field* f) { return f->key == entry.key; });
    if (field == fields.end()) {
      const std::string keys = solver_setting_keys(solver, friction);
      throw CliError("--option " + key + ": not a setting of " + solver +
                         (keys.empty() ? " (it has none besides --tol and --max-iter)"
                                       : " (it accepts " + keys + "; and --tol, --max-iter)"),
                     kExitUsage);
    }
    try {
      (*field)->parse(options, entry.value);
    } catch (const std::invalid_argument& error) {
      throw CliError("--option " + key + ": " + error.what(), kExitUsage);
    }
  }
}

}  // namespace impactbench::cli
