// Event-driven integrator in space: a spinning ball set down on a plane slips until its contact
// point stops, at t* = 2‖c₀‖/(7μg) with c₀ = v₀ + ω₀ × ρ the initial slip velocity, then rolls
// with v = v₀ − (2/7) c₀ (the friction impulse μ m g t* along −c₀/‖c₀‖).
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tests/support/lib/event_complementarity_check.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double r = 0.1, m = 1.0, mu = 0.3, g = 9.81;

void check_sphere_spin(const model::LagrangianSystem<double>& ball) {
  Eigen::VectorXd q(7), v(6);
  q << 0, 0, r, 1, 0, 0, 0;
  const Eigen::Vector3d v0(1.0, 0.5, 0.0), w0(4.0, -6.0, 3.0);
  v << v0, w0;
  const Eigen::Vector3d c0 = v0 + w0.cross(Eigen::Vector3d(0, 0, -r));
  const double t_star = 2 * c0.norm() / (7 * mu * g);
  const EventDrivenIntegrator integrator(ball);
  const auto result = integrator.simulate(q, v, {}, 2 * t_star);
  ASSERT_TRUE(result.succeeded()) << result.message;
  ASSERT_EQ(result.events.size(), 1u);
  EXPECT_EQ(result.events[0].kind, EventKind::kSlipToStick);
  EXPECT_NEAR(result.events[0].t, t_star, 1e-9 * t_star);
  const Eigen::Vector3d v_final = v0 - (2.0 / 7.0) * c0;
  EXPECT_LT((result.v.head<3>() - v_final).norm(), 1e-9);
  // Rolling: the contact point is at rest; the spin about the normal is untouched.
  const Eigen::Vector3d w = result.v.tail<3>();
  EXPECT_LT((result.v.head<3>() + w.cross(Eigen::Vector3d(0, 0, -r))).norm(), 1e-9);
  EXPECT_NEAR(w.z(), w0.z(), 1e-12);
  EXPECT_NEAR(Eigen::Vector4d(result.q.tail<4>()).norm(), 1.0, 1e-9);
  EXPECT_NEAR(result.q[2], r, 1e-12);
  for (const auto& s : result.event_states)
    EXPECT_LE(test_support::acceleration_complementarity_violation(ball, s.q, s.v,
                                                                   Eigen::VectorXd(0), s.modes),
              1e-9);
}

TEST(EventSpatial, SphereSpinSlipToRollOnTestBall) {
  check_sphere_spin(impactbench::test_support::SphereOnPlaneTestSystem(r, m, 9.81, mu, 0.0));
}

TEST(EventSpatial, SphereSpinSlipToRollOnSpatialSystem) {
  model::spatial::SpatialSystemSpec spec;
  model::BodySpec ball;
  ball.name = "ball";
  ball.shape = model::ShapeKind::kSphere;
  ball.radius = r;
  ball.mass = m;
  ball.position = Eigen::Vector3d(0, 0, r);
  spec.bodies.push_back(ball);
  model::StaticPlaneSpec floor;
  floor.normal = Eigen::Vector3d::UnitZ();
  spec.planes.push_back(floor);
  spec.material.friction = mu;
  spec.gravity = g;
  check_sphere_spin(model::spatial::SpatialRigidBodySystem<double>(spec));
}

// A cuboid dropped flat with a sideways velocity lands on its four bottom corners at once: one
// impulse-level friction-contact problem (solve_friction). With e = 0 and μ above
// |v_x⁻| / |v_z⁻| the corners stick, so the box stops dead: v⁺ = 0.
TEST(EventSpatial, FlatCuboidLandingIsOneSimultaneousImpact) {
  model::spatial::SpatialSystemSpec spec;
  model::BodySpec box;
  box.name = "box";
  box.shape = model::ShapeKind::kCuboid;
  box.size = Eigen::Vector3d(0.2, 0.2, 0.1);
  box.mass = m;
  box.position = Eigen::Vector3d(0, 0, 0.05 + 0.01);
  spec.bodies.push_back(box);
  model::StaticPlaneSpec floor;
  floor.normal = Eigen::Vector3d::UnitZ();
  spec.planes.push_back(floor);
  spec.material.friction = 0.5;
  spec.gravity = g;
  const model::spatial::SpatialRigidBodySystem<double> system(spec);
  Eigen::VectorXd q(7), v(6);
  q << 0, 0, 0.06, 1, 0, 0, 0;
  v << 0.5, 0, -1.0, 0, 0, 0;
  const auto result = EventDrivenIntegrator(system).simulate(q, v, {}, 0.2);
  ASSERT_TRUE(result.succeeded()) << result.message;
  std::vector<Event> impacts;
  for (const auto& e : result.events)
    if (e.kind == EventKind::kImpact) impacts.push_back(e);
  ASSERT_EQ(impacts.size(), 4u);
  const double vz = std::sqrt(1.0 + 2 * g * 0.01);
  double total_n = 0.0;
  for (const auto& e : impacts) {
    EXPECT_EQ(e.t, impacts[0].t);
    EXPECT_NEAR(e.t, (std::sqrt(1.0 + 2 * g * 0.01) - 1.0) / g, 1e-9);
    total_n += e.impulse_n;
  }
  EXPECT_NEAR(total_n, m * vz, 1e-8);  // the vertical momentum is absorbed
  for (const auto& st : result.event_states) {
    if (st.t == impacts[0].t) {
      EXPECT_LT(st.v.norm(), 1e-8) << "right after the landing";
    }
  }
  EXPECT_LT(result.v.norm(), 1e-8);
  for (const auto& st : result.event_states)
    EXPECT_LE(test_support::acceleration_complementarity_violation(system, st.q, st.v,
                                                                   Eigen::VectorXd(0), st.modes),
              1e-9);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
