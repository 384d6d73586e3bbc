#pragma once
// A reference engine run of a shipped scenario through the registry `impactbench run` uses,
// measured against the scenario's closed forms (compare::analytic_errors), for the
// reference_engines_* tests.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/settings/setting_fields.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/compare/analytic_errors.hpp"

namespace impactbench::test_support {

/// The value of metric `name`; a test failure (and NaN) when the run has none.
double named(const compare::NamedValues& values, const std::string& name);

/// The index of trajectory column `name` in `names` (positions or velocities); a test failure
/// (and -1) when there is none.
Eigen::Index column_index(const std::vector<std::string>& names, const std::string& name);

/// Runs `engine` on scenario `scenario_name` with the parameter overrides, engine options
/// (--option key=value) and duration (0: the scenario's) and measures it.
compare::NamedValues run_and_measure(
    const std::string& engine, const std::string& scenario_name,
    const scenario::ParameterOverrides& overrides = {}, double duration = 0.0,
    const std::vector<std::pair<std::string, std::string>>& options = {});

/// Expects each key=value of `refused`, given alone as --option to `engine` on scenario
/// `scenario_name`, to be refused with a message naming the key.
void expect_refused_settings(const std::string& engine, const std::string& scenario_name,
                             const std::vector<std::pair<std::string, std::string>>& refused);

}  // namespace impactbench::test_support
