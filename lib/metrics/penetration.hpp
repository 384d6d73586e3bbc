#pragma once
// The deepest penetration of a trajectory, measured on our model's geometry: every contact the
// model finds in every sample (not only the contacts an engine put into its contact problem),
// so that an impact a time-stepper missed shows at its true depth.
#include "lib/model/lagrangian_system.hpp"
#include "lib/output/trajectory.hpp"

namespace impactbench::metrics {

/// max(0, −gap) over every contact of every sample of `trajectory` [m].
double max_penetration(const model::LagrangianSystem<double>& system,
                       const output::Trajectory& trajectory);

}  // namespace impactbench::metrics
