// Event-driven integrator on planar scenarios with analytical solutions: bouncing ball (impact
// times, apex heights, Zeno accumulation time), sliding block (stop time), block on an incline
// pushed by u = k t (stick→slip time), rocking block (Housner's coefficient). After every event
// the acceleration-level complementarity conditions are checked independently. Every scenario
// runs on the test utilities' analytic bodies and on the model library's planar system.
#include <cmath>
#include <memory>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"
#include "tests/support/lib/bouncing_ball_impacts.hpp"
#include "tests/support/lib/event_complementarity_check.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double g = 9.81;

// The ground line through the origin, inclined by `angle` (normal (−sin α, cos α)).
struct Ground {
  double friction = 0.0;
  double restitution = 0.0;
  double angle = 0.0;
  Eigen::Vector2d normal() const { return {-std::sin(angle), std::cos(angle)}; }
  Eigen::Vector2d tangent() const { return {std::cos(angle), std::sin(angle)}; }  ///< up-slope
};

enum class PlanarModel { kTestBody, kPlanarSystem };
using System = std::unique_ptr<model::LagrangianSystem<double>>;

// One disk (shape kDisk) or box, with a force input along `push` when it is non-zero.
System make_body(PlanarModel which, model::ShapeKind shape, double width, double height,
                 double mass, const Ground& ground,
                 const Eigen::Vector2d& push = Eigen::Vector2d::Zero()) {
  const bool disk = shape == model::ShapeKind::kDisk;
  if (which == PlanarModel::kTestBody) {
    const test_support::PlanarTestBody body =
        disk ? test_support::PlanarTestBody{"body", mass, width}
             : test_support::PlanarTestBody{"body", mass, 0.0, width, height};
    auto world = std::make_unique<test_support::PlanarTestWorld>(
        std::vector<test_support::PlanarTestBody>{body}, g, ground.friction, ground.restitution,
        true, ground.angle);
    if (push.norm() > 0.0) world->add_input(0, push);
    return world;
  }
  model::BodySpec body;
  body.name = "body";
  body.shape = shape;
  body.radius = width;
  body.size = Eigen::Vector3d(width, height, 0.0);
  body.mass = mass;
  model::StaticPlaneSpec plane;
  plane.point = Eigen::Vector3d::Zero();
  plane.normal = Eigen::Vector3d(ground.normal().x(), ground.normal().y(), 0.0);
  std::vector<model::ForceInputSpec> inputs;
  if (push.norm() > 0.0) inputs.push_back({"body", Eigen::Vector3d(push.x(), push.y(), 0.0)});
  return std::make_unique<model::planar::PlanarRigidBodySystemd>(
      std::vector<model::BodySpec>{body}, std::vector<model::StaticPlaneSpec>{plane}, g,
      model::Material{ground.friction, ground.restitution}, inputs);
}

class EventPlanar : public ::testing::TestWithParam<PlanarModel> {};

std::string model_name(const ::testing::TestParamInfo<PlanarModel>& param) {
  return param.param == PlanarModel::kTestBody ? "TestBody" : "PlanarSystem";
}

std::vector<Event> events_of_kind(const EventDrivenResult& r, EventKind kind) {
  std::vector<Event> out;
  for (const auto& e : r.events)
    if (e.kind == kind) out.push_back(e);
  return out;
}

void expect_complementarity_after_every_event(const model::LagrangianSystem<double>& system,
                                              const EventDrivenResult& result,
                                              const EventDrivenIntegrator::Input& input) {
  for (const auto& s : result.event_states) {
    const Eigen::VectorXd u =
        system.num_inputs() > 0 ? (input ? input(s.t) : Eigen::VectorXd::Zero(system.num_inputs()))
                                : Eigen::VectorXd(0);
    EXPECT_LE(test_support::acceleration_complementarity_violation(system, s.q, s.v, u, s.modes),
              1e-9)
        << "after the event at t = " << s.t;
  }
}

// Every impact until the Zeno rest is checked: a position error δ changes the next impact speed
// by g δ / v, so the slow late bounces are the sensitive ones.
void check_bouncing_ball(PlanarModel which, double tol) {
  Ground ground;
  ground.restitution = 0.9;
  const double r = 0.1, e = 0.9, h0 = 1.0 - r;
  const System system = make_body(which, model::ShapeKind::kDisk, r, r, 1.0, ground);
  const auto& ball = *system;
  EventDrivenOptions options;
  options.relative_tolerance = options.absolute_tolerance = tol;
  const EventDrivenIntegrator integrator(ball, options);
  const auto result =
      integrator.simulate(Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d::Zero(), {}, 10.0);
  ASSERT_TRUE(result.succeeded()) << result.message;

  const double v1 = std::sqrt(2 * g * h0);
  ASSERT_GE(events_of_kind(result, EventKind::kImpact).size(), 20u);
  test_support::expect_closed_form_impacts(result, {r, h0, e, g}, 1e-9);
  const auto rests = events_of_kind(result, EventKind::kZenoRest);
  ASSERT_EQ(rests.size(), 1u);
  const double t_inf = std::sqrt(2 * h0 / g) + 2 * e * v1 / (g * (1 - e));
  EXPECT_NEAR(rests[0].accumulation_time, t_inf, 1e-6);
  EXPECT_LT(result.events.size(), 200u);
  // At rest afterwards: on the ground, no velocity, gravity carried by the contact.
  EXPECT_NEAR(result.q[1], r, 1e-9);
  EXPECT_LT(result.v.norm(), 1e-9);
  EXPECT_EQ(result.event_states.back().modes.size(), 1u);
  // Energy is conserved between events.
  double energy_after_event = ball.energy(Eigen::Vector3d(0, 1.0, 0), Eigen::Vector3d::Zero());
  std::size_t next_event = 0;
  for (const auto& s : result.samples) {
    if (next_event < result.event_states.size() && s.t >= result.event_states[next_event].t) {
      const auto& es = result.event_states[next_event++];
      energy_after_event = ball.energy(es.q, es.v);
      continue;
    }
    EXPECT_NEAR(s.energy, energy_after_event, 100 * tol) << "t = " << s.t;
  }
  expect_complementarity_after_every_event(ball, result, {});
}

TEST_P(EventPlanar, BouncingBallAtTol1e10) {
  check_bouncing_ball(GetParam(), 1e-10);
}
TEST_P(EventPlanar, BouncingBallAtTol1e12) {
  check_bouncing_ball(GetParam(), 1e-12);
}

TEST_P(EventPlanar, SlidingBlockStopsAtAnalyticalTime) {
  Ground ground;
  ground.friction = 0.5;
  const double mu = 0.5, v0 = 2.0, side = 0.2;
  const System system = make_body(GetParam(), model::ShapeKind::kBox, side, side, 1.0, ground);
  const auto& block = *system;
  const EventDrivenIntegrator integrator(block);
  const auto result =
      integrator.simulate(Eigen::Vector3d(0, side / 2, 0), Eigen::Vector3d(v0, 0, 0), {}, 1.0);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const auto stops = events_of_kind(result, EventKind::kSlipToStick);
  ASSERT_EQ(stops.size(), 2u);  // both bottom corners at once
  for (const auto& stop : stops) EXPECT_NEAR(stop.t, v0 / (mu * g), 1e-9 * v0 / (mu * g));
  EXPECT_NEAR(result.q[0], v0 * v0 / (2 * mu * g), 1e-9);
  EXPECT_NEAR(result.q[1], side / 2, 1e-9);
  EXPECT_NEAR(result.q[2], 0.0, 1e-9);
  EXPECT_LT(result.v.norm(), 1e-9);
  EXPECT_EQ(result.events.size(), 2u);
  expect_complementarity_after_every_event(block, result, {});
}

// A cube resting on an incline of slope β (μ > tan β), pushed down the slope by u = k t at its
// centre: it sticks until m g sin β + k t = μ m g cos β, then slides with acceleration
// k (t − t*) / m, so its speed at T is k (T − t*)² / (2m).
TEST_P(EventPlanar, InclinePushedStickToSlipAtAnalyticalTime) {
  const double beta = 0.2, mu = 0.5, k = 2.0, m = 1.0, side = 0.2, T = 2.0;
  Ground ground;
  ground.friction = mu;
  ground.angle = beta;
  const System system =  // pushed down the slope
      make_body(GetParam(), model::ShapeKind::kBox, side, side, m, ground, -ground.tangent());
  const auto& block = *system;
  const Eigen::Vector2d centre = (side / 2) * ground.normal();
  const EventDrivenIntegrator::Input push = [k](double t) {
    return Eigen::VectorXd::Constant(1, k * t);
  };
  const EventDrivenIntegrator integrator(block);
  const auto result = integrator.simulate(Eigen::Vector3d(centre.x(), centre.y(), beta),
                                          Eigen::Vector3d::Zero(), push, T);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const double t_star = m * g * (mu * std::cos(beta) - std::sin(beta)) / k;
  const auto slips = events_of_kind(result, EventKind::kStickToSlip);
  ASSERT_EQ(slips.size(), 2u);  // both bottom corners at once
  for (const auto& e : slips) EXPECT_NEAR(e.t, t_star, 1e-9 * t_star);
  EXPECT_EQ(result.events.size(), 2u);
  const double speed = -ground.tangent().dot(result.v.head<2>());
  EXPECT_NEAR(speed, k * (T - t_star) * (T - t_star) / (2 * m), 1e-8);
  EXPECT_NEAR(result.v[2], 0.0, 1e-9);
  expect_complementarity_after_every_event(block, result, push);
}

// A slender block released tilted about one bottom corner rocks: every impact of the other
// corner (e = 0, no sliding) conserves the angular momentum about it, which gives Housner's
// ω⁺/ω⁻ = 1 − 1.5 sin²α with α = atan(width / height); the corners alternate. (The ratio
// refers to the pre-impact velocity after the event's drift projection, which puts the pivot
// exactly on the ground at rest.)
TEST_P(EventPlanar, RockingBlockHousnerCoefficient) {
  const double w = 0.2, h = 0.6, theta0 = 0.1;
  Ground ground;
  ground.friction = 1.0;
  const System system = make_body(GetParam(), model::ShapeKind::kBox, w, h, 1.0, ground);
  const auto& block = *system;
  const Eigen::Rotation2Dd R(theta0);
  const Eigen::Vector2d centre = -(R * Eigen::Vector2d(-w / 2, -h / 2));  // left corner at 0
  const EventDrivenIntegrator integrator(block);
  const auto result = integrator.simulate(Eigen::Vector3d(centre.x(), centre.y(), theta0),
                                          Eigen::Vector3d::Zero(), {}, 1.5);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const double alpha = std::atan(w / h);
  const double ratio = 1.0 - 1.5 * std::sin(alpha) * std::sin(alpha);
  const auto impacts = events_of_kind(result, EventKind::kImpact);
  ASSERT_GE(impacts.size(), 4u);
  for (std::size_t k = 0; k < impacts.size(); ++k) {
    const Event& impact = impacts[k];
    if (k > 0) {
      EXPECT_NE(impact.contact, impacts[k - 1].contact) << "t = " << impact.t;
    }
    // The impact's event state is logged at exactly the impact's time: one per impact.
    int matches = 0;
    for (const auto& s : result.event_states) {
      if (s.t != impact.t) continue;
      ++matches;
      EXPECT_NEAR(s.v[2] / s.v_before[2], ratio, 1e-9) << "impact at t = " << impact.t;
    }
    EXPECT_EQ(matches, 1) << "event states at the impact t = " << impact.t;
  }
  // Energy is conserved between the impacts.
  std::size_t next_event = 0;
  double energy_after_event =
      block.energy(Eigen::Vector3d(centre.x(), centre.y(), theta0), Eigen::Vector3d::Zero());
  for (const auto& s : result.samples) {
    if (next_event < result.event_states.size() && s.t >= result.event_states[next_event].t) {
      const auto& es = result.event_states[next_event++];
      energy_after_event = block.energy(es.q, es.v);
      continue;
    }
    EXPECT_NEAR(s.energy, energy_after_event, 1e-8) << "t = " << s.t;
  }
  expect_complementarity_after_every_event(block, result, {});
}

INSTANTIATE_TEST_SUITE_P(Models, EventPlanar,
                         ::testing::Values(PlanarModel::kTestBody, PlanarModel::kPlanarSystem),
                         model_name);

}  // namespace
}  // namespace impactbench::engines::event_driven
