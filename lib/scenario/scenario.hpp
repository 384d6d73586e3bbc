#pragma once
// A benchmark scenario as loaded from scenarios/<name>.toml (format: scenarios/README.md):
// parameters after command-line overrides, the bodies, static planes and inputs derived from
// them, run defaults, which engines may run it, and the analytical quantities that tests
// check simulations against.
//
// A Scenario is a value: copies share the compiled expressions (input u(t), analytic
// quantities), which are evaluated under a lock and are safe to use from several threads.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/model/body_spec.hpp"
#include "lib/scenario/engine_catalog.hpp"
#include "lib/scenario/scenario_error.hpp"

namespace impactbench::scenario {

enum class Dimension { kPlanar, kSpatial };
enum class SystemKind {
  kRigidBodies,  ///< free rigid bodies and static planes, built from `bodies` and `planes`
  kPlankBox,     ///< the analytic plank–box model of the source's appendix F (parameters)
};

std::string to_string(Dimension dimension);
std::string to_string(SystemKind system);

struct Parameter {
  std::string name;
  double value = 0.0;          ///< after overrides
  double default_value = 0.0;  ///< as written in the file
  std::string unit;
  std::string description;
};

struct AnalyticQuantity {
  std::string name;
  std::string expression;  ///< source text
  std::string unit;
  std::string description;
  bool indexed = false;  ///< the expression uses the index k
};

class ScenarioFunctions;  // compiled u(t) and analytic expressions (scenario_functions.hpp)

struct Scenario {
  std::string name;
  std::string description;
  std::filesystem::path path;
  Dimension dimension = Dimension::kPlanar;
  SystemKind system = SystemKind::kRigidBodies;
  std::vector<Parameter> parameters;  ///< in file order
  double duration = 0.0;              ///< [s]
  double dt = 0.0;                    ///< default time step [s] (time-stepping engines)
  double tolerance = 0.0;             ///< default event/integration tolerance (event-driven)
  /// Whether `compare` measures runs against a reference trajectory (false for piles, whose
  /// motion is chaotic: a second run at a finer step diverges from the first).
  bool reference_trajectory = true;
  std::vector<std::string> engines;  ///< subset of the catalog's engine names
  /// [settings.ENGINE] tables: engine → key = value (as text), checked against the engine's
  /// settings on load; engines::resolve_run_options applies them over the engine's defaults.
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> engine_settings;
  model::Material material;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  ///< (0, -g, 0) planar, (0, 0, -g) spatial
  std::vector<model::BodySpec> bodies;
  std::vector<model::StaticPlaneSpec> planes;
  std::vector<model::ForceInputSpec> inputs;          ///< channel k of input(t) acts as inputs[k]
  std::vector<AnalyticQuantity> analytic_quantities;  ///< in file order

  /// Value of a parameter after overrides; throws std::invalid_argument listing the valid names.
  double parameter(const std::string& name) const;
  const Parameter* find_parameter(const std::string& name) const;
  const model::BodySpec* find_body(const std::string& name) const;
  bool supports_engine(const std::string& engine) const;

  /// u(t): one magnitude [N] per entry of `inputs`.
  Eigen::VectorXd input(double t) const;
  /// An analytic quantity, with index k (e.g. the k-th impact) where the expression uses it.
  /// Throws std::invalid_argument for an unknown name. The value may be NaN or Inf where the
  /// formula does not apply (e.g. t_inf for e = 1).
  double analytic(const std::string& name, int k = 0) const;
  bool has_analytic(const std::string& name) const;

  std::shared_ptr<const ScenarioFunctions> functions;
};

/// Overrides `--set name=value`, applied to parameters before anything is derived from them.
using ParameterOverrides = std::map<std::string, double>;

/// Loads and validates a scenario file; every problem throws ScenarioError. A `duration` given
/// (--duration) replaces the file's, whose formula is then not evaluated: a run that sets its
/// own duration is not stopped by a duration formula that fails for the user's parameters.
/// `engines` checks the file's engines and their settings (the engine registry's catalog,
/// which the registry's scenario_loading.hpp passes for every program).
Scenario load_scenario(const EngineCatalog& engines, const std::filesystem::path& path,
                       const ParameterOverrides& overrides = {},
                       std::optional<double> duration = std::nullopt);

/// The scenario directory: $IMPACTBENCH_SCENARIOS if set, else the source tree's scenarios/.
std::filesystem::path scenario_directory();
/// Names (file stems of *.toml) in the scenario directory, sorted.
std::vector<std::string> list_scenarios();
/// Loads <scenario_directory>/<name>.toml; an unknown name throws ScenarioError listing the
/// available ones.
Scenario load_scenario_by_name(const EngineCatalog& engines, const std::string& name,
                               const ParameterOverrides& overrides = {},
                               std::optional<double> duration = std::nullopt);

/// Parses "name=value" as given to --set; throws std::invalid_argument when malformed.
std::pair<std::string, double> parse_override(const std::string& assignment);

}  // namespace impactbench::scenario
