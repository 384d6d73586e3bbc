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
#include "tests/support/lib/event_driven_runs.hpp"
#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::EventRuns;
using test_support::SpatialScene;

// The prediction through the end of a 3-D slip has an accuracy floor of its own, which the
// central differences resolve and the trajectory ratios (forward differences, error ~ε²·O(1)) do
// not. Measured on these two configurations (‖P z(T)‖ = 4.7 and 2.1): the error of the central
// quotient is C ε² + F with F = 1.4e-7 and 6.9e-8, flat from ε = 2e-3 down to 2.5e-4, so it is no
// difference noise (that would grow as 1/ε) and no event-location error (the engine's slip end
// matches t* = 2|c0|/(7μg) to 1e-15 s at tolerances 1e-10 to 1e-14). It is the prediction's:
// TrajectorySensitivity integrates the singular slip flow on a graded grid that stops τ =
// 2⁻²⁴ × 1e-3 s ≈ 6e-11 s before the event, where ‖ζ_t‖ = (7/2) μ g τ ≈ 6e-10 m/s and the
// direction ε(ζ_t) carries the round-off of ζ_t (~1e-16 m/s) relative to that: F grew to 1.5e-6
// when τ was made 4× smaller (max_step 2.5e-4), as u/τ predicts. So the ε range is chosen where
// C ε² dominates F: the error ratio per halving, (4Cε² + F)/(Cε² + F), stays ≥ 3 (the slope
// bound log2 3 of expect_quadratic) while C ε² ≥ 2F; with C ≈ 0.054 (8.7e-7 at ε = 4e-3) and
// F ≤ 1.4e-7 that is ε ≥ 2.3e-3, hence ε = 1.6e-2, 8e-3, 4e-3 (measured slopes 2.00–2.03).
TEST(SpatialSlipToStick, SpinningSphereStartsRolling) {
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
    test_support::expect_spatial_first_order(
        scene, runs, 71 + k, "sphere slip to roll " + std::to_string(k), {1.6e-2, 8e-3, 4e-3});
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
