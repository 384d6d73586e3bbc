// Spatial sensitivity through single impacts and lift-off (source B.3 with spatial friction, C):
// a sphere launched at random (fixed seed) onto the ground, impacting into slip (Γ < 0,
// Λ_t opposite to the post-impact sliding) or into stick (Γ ≥ 0), bouncing with a slip or stick
// impulse, and a sphere lifted off the ground by a rising input force while rolling or sliding.
// For each, the first-order prediction of the sensitivity module along the event-driven
// engine's nominal must match
//   - runs of the engine from perturbed initial states and inputs, over the whole trajectory,
//     with an error ratio e(ε)/e(ε/2) ≈ 4 (sensitivity_convergence.hpp), and
//   - central finite differences of the engine's end state, in tangent coordinates
//     (orientation perturbations as world rotation vectors), with errors shrinking as ε².
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/sensitivity/jump_gain.hpp"
#include "tests/support/lib/event_driven_runs.hpp"
#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

namespace ed = engines::event_driven;
using test_support::EventRuns;
using test_support::SpatialScene;

constexpr double kEnd = 0.15;

/// Random launch: from 5 cm above the ground, with the given approach speed and a tangential
/// velocity and spin drawn from the generator.
SpatialScene launched(std::mt19937& rng, double tangential, double friction, double restitution) {
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI), spin(-3.0, 3.0);
  const double a = angle(rng);
  const Eigen::Vector3d v(tangential * std::cos(a), tangential * std::sin(a), -1.0);
  const Eigen::Vector3d w(spin(rng), spin(rng), spin(rng));
  return SpatialScene(test_support::sphere_over_ground(0.15, v, w, friction, restitution));
}

TEST(SpatialSingleImpact, IntoSlipOrStickAsGammaChooses) {
  // e = 0. Γ < 0 (fast sliding, μ = 0.3): slip after the impact (which may end in rolling
  // before kEnd); Γ ≥ 0 (slow, μ = 0.8): stick (rolling) at once.
  const struct {
    double tangential, friction;
    ContactPhase phase;
    unsigned seed;
  } cases[] = {{2.0, 0.3, ContactPhase::kSlipPositive, 11}, {0.3, 0.8, ContactPhase::kStick, 12}};
  for (const auto& c : cases) {
    std::mt19937 rng(c.seed);
    for (int k = 0; k < 2; ++k) {
      const SpatialScene scene = launched(rng, c.tangential, c.friction, 0.0);
      EventRuns runs(scene.system(), scene.model(), kEnd);
      const auto events = test_support::engine_micro_events(scene, runs, kEnd);
      ASSERT_GE(events.size(), 1u);
      EXPECT_EQ(events[0].kind, GuardKind::kImpact);
      EXPECT_EQ(events[0].phase_after, c.phase);
      runs.directions = 6;
      test_support::expect_spatial_first_order(
          scene, runs, c.seed + 10 * (k + 1),
          "sphere impact into " + std::string(to_string(c.phase)) + " " + std::to_string(k));
    }
  }
}

TEST(SpatialSingleImpact, BouncesWithTheImpulseGammaChooses) {
  std::mt19937 rng(13);
  // Γ < 0 (fast sliding, small μ): slip impulse; Γ ≥ 0 (slow, large μ): stick impulse.
  const struct {
    double tangential, friction;
    ContactPhase law;
  } cases[] = {{2.0, 0.2, ContactPhase::kSlipPositive}, {0.3, 0.9, ContactPhase::kStick}};
  for (const auto& c : cases) {
    const SpatialScene scene = launched(rng, c.tangential, c.friction, 0.6);
    EventRuns runs(scene.system(), scene.model(), kEnd);
    const auto events = test_support::engine_micro_events(scene, runs, kEnd);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].phase_after, ContactPhase::kOpen);
    EXPECT_EQ(events[0].bounce_impulse, c.law);
    runs.directions = 6;
    test_support::expect_spatial_first_order(
        scene, runs, 41, "sphere bounce, " + std::string(to_string(c.law)) + " impulse");
  }
}

TEST(SpatialLiftOff, FromSliding) {
  // On the ground (gap 0), sliding, pulled up by u(t) = 20 t N: λ_n = m g − u reaches 0 at
  // 0.49 s. (A rolling sphere is no test of lift-off alone: its stick force is zero, so the
  // stick→slip guard μ λ_n − ‖λ_t‖ reaches zero together with λ_n, a double event.)
  const SpatialScene scene(test_support::sphere_over_ground(0.1, Eigen::Vector3d(1.0, 0.5, 0.0),
                                                            Eigen::Vector3d(0.0, 0.0, 2.0), 0.02,
                                                            0.0, {Eigen::Vector3d::UnitZ()}));
  EventRuns runs(scene.system(), scene.model(), 0.6);
  // The prediction error at ε = 5e-6 is ~1e-12: the engine's tolerance must be below it.
  runs.options.relative_tolerance = runs.options.absolute_tolerance = 1e-14;
  runs.input = [](double t) { return Eigen::VectorXd::Constant(1, 20.0 * t); };
  runs.input_rate = [](double) { return Eigen::VectorXd::Constant(1, 20.0); };
  const auto events = test_support::engine_micro_events(scene, runs, 0.6);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, GuardKind::kLiftOff);
  runs.directions = 6;
  test_support::expect_spatial_first_order(scene, runs, 51, "sphere lift-off from slip");
}

TEST(SpatialSingleImpact, AGrazingContactIsRefusedWithOneClearMessage) {
  // The sphere touches the ground (gap 0) moving only sideways: the impact guard's rate
  // D_xγ f = ζ_n is 0, the crossing is tangential and the jump gain (C.37, division by the rate)
  // does not exist; the module says so instead of dividing by zero.
  const SpatialScene scene(test_support::sphere_over_ground(0.1, Eigen::Vector3d(1.0, 0.0, 0.0),
                                                            Eigen::Vector3d::Zero(), 0.3, 0.0));
  const HybridMode open{ContactPhase::kOpen};
  const MicroEvent impact{0, GuardKind::kImpact, ContactPhase::kSlipPositive};
  try {
    linearise_micro_event(scene.model(), open, impact, scene.x0(), Eigen::VectorXd(),
                          Eigen::VectorXd());
    ADD_FAILURE() << "a grazing impact was linearised";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the guard is not crossed transversally (rate 0,"), std::string::npos)
        << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace impactbench::sensitivity
