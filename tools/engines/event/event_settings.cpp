#include "tools/engines/event/event_settings.hpp"

#include <algorithm>
#include <limits>

#include "solvers/friction/friction_solvers.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/engines/engine_names.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using O = EventDrivenOptions;

std::vector<std::string> names_of(const std::vector<solvers::SolverInfo>& registry) {
  std::vector<std::string> names;
  for (const auto& info : registry) names.push_back(info.name);
  return names;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const SettingsSchema<EventDrivenOptions>& event_settings_schema() {
  // Whole-number limits: beyond them a run does not end in useful time.
  static const SettingsSchema<O> schema(
      engine_name::kEvent, "the event-driven engine",
      {number_field("rtol", &O::relative_tolerance, {0.0, 1.0, true}),
       number_field("atol", &O::absolute_tolerance, {0.0, kInf, true}),
       choice_field<O, FlowMethod>("method", &O::method,
                                   {{"bdf", FlowMethod::kBdf},
                                    {"adams", FlowMethod::kAdams},
                                    {"erk", FlowMethod::kErk},
                                    {"own_erk", FlowMethod::kOwnErk}}),
       choice_field<O, ErkPair>("erk_pair", &O::erk_pair,
                                {{"dopri5", ErkPair::kDormandPrince54},
                                 {"verner6", ErkPair::kVerner65},
                                 {"fehlberg8", ErkPair::kFehlberg87}}),
       // CVODE's orders stop at 12 (Adams) and 5 (BDF): a larger startup_order never lifts.
       whole_field("startup_order", &O::startup_order, 0, 12),
       switch_field("dense_output_root_search", &O::dense_output_root_search),
       whole_field("max_events", &O::max_events, 1, 10000000),
       number_field("output_interval", &O::output_interval, {0.0, kInf}),
       number_field("max_step", &O::max_step, {0.0, kInf}),
       whole_field("zeno_impact_count", &O::zeno_impact_count, 1, 1000000),
       number_field("zeno_velocity", &O::zeno_velocity, {0.0, kInf}),
       number_field("zeno_min_interval", &O::zeno_min_interval, {0.0, kInf}),
       number_field("contact_margin", &O::contact_margin, {0.0, kInf, true}),
       number_field("gap_tolerance", &O::gap_tolerance, {0.0, kInf}),
       number_field("velocity_tolerance", &O::velocity_tolerance, {0.0, kInf}),
       name_field("lcp_solver", &O::lcp_solver, names_of(solvers::lcp_solvers())),
       name_field("friction_solver", &O::friction_solver, names_of(solvers::friction_solvers()))});
  return schema;
}

const EngineSettings& event_settings() {
  static const EngineSettings settings = [] {
    EngineSettings s = event_settings_schema().describe();
    s.tolerance_keys = {"rtol", "atol"};
    s.solver_key = [](const std::string& name) {
      const auto lcp = names_of(solvers::lcp_solvers());
      const auto friction = names_of(solvers::friction_solvers());
      if (contains(lcp, name)) return std::string("lcp_solver");
      if (contains(friction, name)) return std::string("friction_solver");
      throw SettingError(engine_name::kEvent, "solver",
                         "must be an LCP solver (" + join_names(lcp) + ") or a friction solver (" +
                             join_names(friction) + "), got '" + name.substr(0, 40) + "'");
    };
    return s;
  }();
  return settings;
}

}  // namespace impactbench::engines::event_driven
