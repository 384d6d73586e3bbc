#pragma once
// Errors of a run against the closed-form quantities its scenario file states ([analytic]):
// each check applies only where the scenario defines the quantities it needs.
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::compare {

using NamedValues = std::vector<std::pair<std::string, double>>;

/// The value named `name`, or NaN when there is none (a metric that does not apply).
double named_value(const NamedValues& values, const std::string& name);

/// How many bounces the apex and impact-time errors cover.
inline constexpr int kCheckedBounces = 5;

/// Named errors (measured − analytical, largest magnitude over the checked features), e.g.
/// apex_error, impact_time_error, stop_time_error, stop_distance_error. NaN where a run does not
/// show the feature at all (e.g. a ball that stopped bouncing).
NamedValues analytic_errors(const scenario::Scenario& scenario, const engines::RunResult& run);

}  // namespace impactbench::compare
