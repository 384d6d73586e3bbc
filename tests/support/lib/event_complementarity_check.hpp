#pragma once
// Independent check of the acceleration-level complementarity conditions after an event of the
// event-driven integrator: given the post-event state and the modes it chose, re-solve the
// constrained dynamics as one least-squares KKT system (not the engine's Delassus solve) and
// measure the worst violation of
//   closed:   λ_n ≥ 0 (a_n = 0 holds by construction);
//   stick:    Σ‖λ_t‖ ≤ μ Σλ_n over the sticking contacts (aggregate, because redundant stick
//             constraints of one body leave the split undetermined; sufficient for contacts
//             of one body on one line/plane);
//   slip:     with ζ_t = 0 the slip direction must agree with the tangential acceleration;
//   open and touching (gap ≈ 0, ζ_n ≈ 0): a_n ≥ 0.
#include <map>

#include <Eigen/Core>

#include "lib/engines/event_driven/event_types.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_support {

/// Worst violation, in units of the free generalized force (forces) or acceleration.
double acceleration_complementarity_violation(
    const model::LagrangianSystem<double>& system, const Eigen::VectorXd& q,
    const Eigen::VectorXd& v, const Eigen::VectorXd& u,
    const std::map<model::ContactKey, engines::event_driven::ContactMode>& modes);

}  // namespace impactbench::test_support
