#pragma once
// The settings under which engines are compared at equal work (issue #13's table), as the
// engine registry lists them with each engine (EngineInfo::equal_work): Moreau–Jean with 10
// Gauss–Seidel sweeps per step, Box2D with 8 velocity and 3 position iterations, Bullet with 10
// solver iterations, MuJoCo with 10 PGS sweeps. The benchmark binary and the suite's equal-work
// table both use these.
#include <string>
#include <utility>
#include <vector>

#include "lib/engines/run_result.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::engines {

/// `--option` pairs of `engine` at equal work; empty for an engine without such settings.
std::vector<std::pair<std::string, std::string>> equal_work_settings(const std::string& engine);

/// The engines that have equal-work settings, Moreau–Jean first.
const std::vector<std::string>& equal_work_engines();

/// Engine CPU seconds per step of `options.engine` run on `scenario` as a bare loop (a
/// timing-only run, RecordingOptions::timing_only: nothing of ours between its steps, nothing
/// kept). Throws what the run throws.
double bare_loop_seconds_per_step(const scenario::Scenario& scenario, RunOptions options);

}  // namespace impactbench::engines
