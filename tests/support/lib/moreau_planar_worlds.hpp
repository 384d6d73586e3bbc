#pragma once
// Planar worlds for the Moreau–Jean tests, built from the same specs either as the project's
// PlanarRigidBodySystem or as the independent PlanarTestWorld, so every planar acceptance test
// runs on both (and a disagreement points at the system, not the stepper).
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lib/model/body_spec.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::test_support {

enum class PlanarKind { kProjectSystem, kTestWorld };

std::string to_string(PlanarKind kind);

struct PlanarWorldSpec {
  std::vector<model::BodySpec> bodies;  ///< kDisk or kBox
  bool has_ground = true;
  double ground_angle = 0.0;  ///< ground line through the origin, normal (−sin α, cos α)
  double gravity = 9.81;
  model::Material material;
  std::vector<model::ForceInputSpec> inputs;
};

std::unique_ptr<model::LagrangianSystem<double>> make_planar_world(PlanarKind kind,
                                                                   const PlanarWorldSpec& spec);

/// Both kinds, for INSTANTIATE_TEST_SUITE_P, and the matching test-name generator.
inline auto all_planar_kinds() {
  return ::testing::Values(PlanarKind::kProjectSystem, PlanarKind::kTestWorld);
}
inline std::string planar_kind_name(const ::testing::TestParamInfo<PlanarKind>& info) {
  return to_string(info.param);
}

model::BodySpec disk(const std::string& name, double radius, double mass);
model::BodySpec box(const std::string& name, double width, double height, double mass);

}  // namespace impactbench::test_support
