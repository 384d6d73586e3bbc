// Event-driven integrator in space through a stick→slip onset. A 0.4 × 0.3 × 0.2 m cuboid
// held with one body diagonal 0.04 rad off the vertical falls 2 cm onto that corner (e = 0,
// μ = 0.2), sticks, and tips over; the friction that holds the corner grows until it reaches
// the cone and the corner starts to slip. The slip velocity grows from zero like (t − t*)², in a
// direction the flow turns from −λ_t(t*) at a rate μλ_n W/‖ζ_t‖ that has no bound at the
// onset, so this is the case the flow integrator finds hardest (constrained_flow.hpp,
// slip_direction). There is no closed form; the checks are an independent solver and two
// integrators:
// - Moreau–Jean converges to the event-driven run at first order: the distance of the
//   positions at t = 0.45 s (after the onset at t ≈ 0.352 s, before any other corner lands)
//   halves as h halves (measured 5.3e-5, 2.7e-5, 1.4e-5 for h = 50, 25, 12.5 µs);
// - Adams (the default) and BDF, which take different steps through the stiff onset, agree
//   (measured 2.1e-9 apart at t = 0.5 s with rtol = atol = 1e-12); the explicit ERK pair
//   cannot follow the onset and says so.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/engines/moreau_jean/moreau_jean_stepper.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "tests/support/lib/event_complementarity_check.hpp"

namespace impactbench::engines::event_driven {
namespace {

constexpr double kFriction = 0.2;
constexpr double kEnd = 0.45;

model::spatial::SpatialSystemSpec corner_spec() {
  model::spatial::SpatialSystemSpec spec;
  model::BodySpec box;
  box.name = "box";
  box.shape = model::ShapeKind::kCuboid;
  box.size = Eigen::Vector3d(0.4, 0.3, 0.2);
  box.mass = 1.0;
  // The corner (−0.2, −0.15, −0.1) straight below the centre, then tilted by 0.04 rad about
  // (0.6, 0.8, 0); the centre is 2 cm above the corner's touchdown height.
  box.orientation = Eigen::Quaterniond(0.8310409345784268, 0.34624615669357484, -0.4351651573911775,
                                       -0.010763355548135577);
  box.position = Eigen::Vector3d(0, 0, 0.2890428624837871);
  box.velocity = Eigen::Vector3d(0.05, 0.02, -1.0);
  spec.bodies.push_back(box);
  model::StaticPlaneSpec floor;
  floor.normal = Eigen::Vector3d::UnitZ();
  spec.planes.push_back(floor);
  spec.material.friction = kFriction;
  spec.gravity = 9.81;
  return spec;
}

struct Start {
  Eigen::VectorXd q, v;
};

Start start_of(const model::spatial::SpatialSystemSpec& spec) {
  const model::BodySpec& box = spec.bodies.front();
  Start s{Eigen::VectorXd(7), Eigen::VectorXd(6)};
  s.q << box.position, box.orientation.w(), box.orientation.x(), box.orientation.y(),
      box.orientation.z();
  s.v << box.velocity, box.angular_velocity;
  return s;
}

EventDrivenResult event_run(const model::LagrangianSystem<double>& system, const Start& start,
                            FlowMethod method, double duration) {
  EventDrivenOptions options;
  options.method = method;
  options.relative_tolerance = options.absolute_tolerance = 1e-12;
  return EventDrivenIntegrator(system, options).simulate(start.q, start.v, {}, duration);
}

double position_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a.head<7>() - b.head<7>()).cwiseAbs().maxCoeff();
}

TEST(EventSpatialStickToSlip, CornerSticksThenSlipsWithBothMultistepMethods) {
  const auto spec = corner_spec();
  const model::spatial::SpatialRigidBodySystem<double> system(spec);
  const Start start = start_of(spec);
  std::vector<EventDrivenResult> runs;
  for (FlowMethod method : {FlowMethod::kAdams, FlowMethod::kBdf}) {
    runs.push_back(event_run(system, start, method, 0.5));
    const EventDrivenResult& run = runs.back();
    ASSERT_TRUE(run.succeeded()) << run.message;
    ASSERT_GE(run.events.size(), 2u);
    EXPECT_EQ(run.events[0].kind, EventKind::kImpact);
    EXPECT_EQ(run.events[0].to_mode, ContactMode::kStick);
    EXPECT_EQ(run.events[1].kind, EventKind::kStickToSlip);
    EXPECT_EQ(run.events[1].contact, run.events[0].contact);
    EXPECT_GT(run.events[1].t, 0.3);
    EXPECT_LT(run.events[1].t, kEnd);
    for (const auto& s : run.event_states)
      EXPECT_LE(test_support::acceleration_complementarity_violation(system, s.q, s.v,
                                                                     Eigen::VectorXd(0), s.modes),
                1e-9);
  }
  EXPECT_NEAR(runs[0].events[1].t, runs[1].events[1].t, 1e-9);
  const double apart =
      std::max(position_distance(runs[0].q, runs[1].q), (runs[0].v - runs[1].v).norm());
  std::printf("stick-to-slip at %.12g s; Adams and BDF %.3g apart at t = 0.5 s\n",
              runs[1].events[1].t, apart);
  EXPECT_LT(apart, 1e-7);
}

// The explicit pair cannot follow the onset's stiffness; its failure names the method that can.
TEST(EventSpatialStickToSlip, ExplicitPairStopsAtTheOnsetNamingBdf) {
  const auto spec = corner_spec();
  const model::spatial::SpatialRigidBodySystem<double> system(spec);
  const EventDrivenResult run = event_run(system, start_of(spec), FlowMethod::kErk, kEnd);
  ASSERT_FALSE(run.succeeded());
  EXPECT_EQ(run.status, SimulationStatus::kIntegratorFailure);
  EXPECT_NE(run.message.find("ARK_ERR_FAILURE"), std::string::npos) << run.message;
  EXPECT_NE(run.message.find("run it with --option method=bdf"), std::string::npos) << run.message;
  ASSERT_GE(run.events.size(), 2u);
  EXPECT_EQ(run.events[1].kind, EventKind::kStickToSlip);
}

TEST(EventSpatialStickToSlip, MoreauJeanConvergesToTheRunAtFirstOrder) {
  const auto spec = corner_spec();
  const model::spatial::SpatialRigidBodySystem<double> system(spec);
  const Start start = start_of(spec);
  const EventDrivenResult reference = event_run(system, start, FlowMethod::kBdf, kEnd);
  ASSERT_TRUE(reference.succeeded()) << reference.message;
  std::vector<double> distances;
  for (double dt : {50e-6, 25e-6, 12.5e-6}) {
    moreau_jean::MoreauJeanOptions options;
    options.dt = dt;
    options.record_impulses = false;
    moreau_jean::MoreauJeanStepper stepper(system, options);
    const auto result = stepper.simulate(start.q, start.v, {}, kEnd);
    ASSERT_TRUE(result.succeeded()) << result.message;
    ASSERT_NEAR(result.final_state.t, kEnd, 1e-9);
    distances.push_back(position_distance(result.final_state.q, reference.q));
    std::printf("h = %g s: positions %.3g from the event-driven run\n", dt, distances.back());
  }
  // First order: each halving of h halves the distance (the ratio 2 less a margin for the
  // O(h²) terms and the phase of the landing within a step, moreau_event_convergence_test).
  for (std::size_t i = 1; i < distances.size(); ++i)
    EXPECT_GT(distances[i - 1] / distances[i], 1.6) << i;
}

}  // namespace
}  // namespace impactbench::engines::event_driven
