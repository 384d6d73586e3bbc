#pragma once
// The contacts of one step as the metrics and events want them, from what an engine that
// reports a contact point, normal, depth and impulse per contact (ODE, MuJoCo) found: one
// ContactSample per point (impulse and post-step relative velocity in the tangent frame of
// contact_frame.hpp) and one ClosedContact per pair of bodies (approach speed at the step's
// start, summed impulses).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/contact_events.hpp"
#include "lib/engines/run_result.hpp"
#include "tools/engines/fixed_step/scene_state.hpp"

namespace impactbench::adapters {

/// One contact point of a step. The normal points from body 2 to body 1.
struct PointContact {
  std::string pair;                                 ///< "<body 1>-<body 2>"
  int body1 = 0;                                    ///< index into the scene's bodies
  int body2 = -1;                                   ///< -1: a boundary
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< at the step's start
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double depth = 0.0;                                 ///< penetration at the step's start [m]
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();  ///< on body 1 over the step [N·s]
};

/// Appends the samples to step.contacts and returns the closed pairs; raises max_penetration
/// to the deepest contact. `before` and `after` are the bodies at the step's start and end.
std::vector<engines::ClosedContact> record_step_contacts(const ReferenceScene& scene,
                                                         const std::vector<PointContact>& contacts,
                                                         const std::vector<BodyState>& before,
                                                         const std::vector<BodyState>& after,
                                                         engines::StepRecord& step,
                                                         double& max_penetration);

}  // namespace impactbench::adapters
