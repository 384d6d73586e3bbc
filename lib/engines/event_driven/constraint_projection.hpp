#pragma once
// Removes the drift of the closed contacts' constraints, which the flow enforces only at
// acceleration level: the least M-norm corrections with h_n = 0 and ζ_n = 0 (and ζ_t = 0 when
// sticking). Done at every event, so drift never accumulates over segments.
#include <Eigen/Core>

#include "lib/engines/event_driven/contact_modes.hpp"
#include "lib/engines/event_driven/run_context.hpp"

namespace impactbench::engines::event_driven {

void project_onto_closed_constraints(const RunContext& run, const ContactModes& modes,
                                     Eigen::VectorXd& q, Eigen::VectorXd& v);

}  // namespace impactbench::engines::event_driven
