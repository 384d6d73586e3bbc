// Spatial sensitivity of cuboids landing on the ground (source C.2, D in 3-D): on a corner (one
// impact); on an edge (two corners at once): with the landing edge nearly below the centre of
// mass a conewise-constant gain, one per micro-event order, and tilted less an order-dependent
// outcome (the second impact lifts the first corner off) that has no gain and is refused; flat
// (four corners at once), which never has a gain (proved below) and is refused. Tilts and
// directions drawn with fixed seeds; the ε-tests of sensitivity_spatial_impact_test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

#include "lib/sensitivity/event_driven_nominal.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/support/lib/event_driven_runs.hpp"
#include "tests/support/lib/spatial_sensitivity_scenes.hpp"

namespace impactbench::sensitivity {
namespace {

using test_support::EventRuns;
using test_support::SpatialScene;

/// The centre height at which the lowest corner of the cuboid (half sizes 0.2, 0.15, 0.1) in
/// `orientation` is `clearance` above the ground.
double height_for(const Eigen::Quaterniond& orientation, double clearance) {
  const Eigen::Matrix3d R = orientation.toRotationMatrix();
  const Eigen::Vector3d half(0.2, 0.15, 0.1);
  // Lowest corner: −Σ |R_zj| h_j below the centre.
  return clearance + (R.row(2).cwiseAbs().transpose().cwiseProduct(half)).sum();
}

/// A frictionless, inelastic cuboid tilted by `tilt` about the world x axis and spinning about
/// it, 2 cm above the ground: the two corners of its lowest edge keep equal heights and land at
/// once.
model::spatial::SpatialSystemSpec edge_landing(double tilt) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitX()));
  return test_support::cuboid_over_ground(height_for(q, 0.02), q, Eigen::Vector3d(0.3, -0.2, -1.0),
                                          Eigen::Vector3d(0.5, 0.0, 0.0), 0.0, 0.0);
}

/// The module refuses `nominal` in one line naming the pulling impact.
void expect_refused_as_order_dependent(const SpatialScene& scene, const NominalTrajectory& nominal,
                                       const std::string& what) {
  try {
    const TrajectorySensitivity sensitivity(scene.model(), nominal);
    ADD_FAILURE() << what << " was linearised";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("pulls on closed contact"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

/// W_ij = w_n,iᵀ M⁻¹ w_n,j for the listed contacts at positions q (the normal Delassus
/// matrix: the normal velocity of contact i per unit normal impulse at contact j).
Eigen::MatrixXd normal_delassus(const SpatialScene& scene, const Eigen::VectorXd& q,
                                const Eigen::VectorXd& v, const std::vector<int>& which) {
  const auto& system = scene.system();
  const int nv = system.num_velocities();
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(q, v, 1e3, contacts);  // the model's contact list and order
  Eigen::MatrixXd Wn(nv, static_cast<Eigen::Index>(which.size()));
  for (std::size_t k = 0; k < which.size(); ++k)
    Wn.col(static_cast<Eigen::Index>(k)) = contacts.at(which[k]).normal_direction(nv);
  return Wn.transpose() * Eigen::MatrixXd(system.mass_matrix(q)).ldlt().solve(Wn);
}

/// The instant of the run's first event: positions and pre-impact velocities.
const engines::event_driven::EventState& first_instant(
    const engines::event_driven::EventDrivenResult& run) {
  const auto& states = run.event_states;
  const double t = run.events.at(0).t;
  return *std::find_if(states.begin(), states.end(), [&](const auto& s) { return s.t == t; });
}

/// x0 turned by the angle `angle` about the world y axis (tangent coordinates, first order).
Eigen::VectorXd tilted_about_y(const SpatialScene& scene, const Eigen::VectorXd& x0, double angle) {
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(2 * scene.system().num_velocities());
  delta(4) = 1.0;  // (δc, δθ, δv, δω): δθ_y
  return x0 + angle * (scene.model().tangent_basis(x0) * delta);
}

/// A cuboid with a generic small tilt (one corner lowest; tilts drawn with seed 81) landing
/// with velocity v and angular velocity w, e = 0: one impact, whose map the engine chooses by Γ
/// (`expected_map`), then 15–17 ms on that corner before the run ends, before another corner
/// comes down. The ε-tests of expect_spatial_first_order with 6 random directions.
void expect_corner_landing(double friction, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
                           engines::event_driven::ContactMode expected_map,
                           const std::string& label) {
  std::mt19937 rng(81);
  std::uniform_real_distribution<double> tilt(0.05, 0.15), sign(-1.0, 1.0);
  const Eigen::Quaterniond q =
      Eigen::AngleAxisd(std::copysign(tilt(rng), sign(rng)), Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(std::copysign(tilt(rng), sign(rng)), Eigen::Vector3d::UnitY()) *
      Eigen::Quaterniond::Identity();
  const SpatialScene scene(
      test_support::cuboid_over_ground(height_for(q, 0.02), q, v, w, friction, 0.0));
  const double end = 0.035;
  EventRuns runs(scene.system(), scene.model(), end);
  const auto run = runs.run(scene.x0(), {});
  ASSERT_TRUE(run.succeeded()) << run.message;
  ASSERT_EQ(run.events.size(), 1u) << label;
  EXPECT_EQ(run.events[0].kind, engines::event_driven::EventKind::kImpact) << label;
  if (friction > 0.0) {
    EXPECT_EQ(run.events[0].impact_map, expected_map) << label;
  }
  std::cout << label << ": impact at " << run.events[0].t << " s, Γ = " << run.events[0].gamma
            << "\n";
  runs.directions = 6;
  test_support::expect_spatial_first_order(scene, runs, 83, label);
}

TEST(SpatialLanding, OnACornerFrictionless) {
  expect_corner_landing(0.0, Eigen::Vector3d(0.3, -0.2, -1.0), Eigen::Vector3d(0.5, -0.4, 0.3),
                        engines::event_driven::ContactMode::kSlip,
                        "cuboid on a corner, frictionless");
}

TEST(SpatialLanding, OnACornerIntoSlip) {
  // μ = 0.5: Γ < 0, the corner slips after the impact, its slip direction turning with the
  // body's rotation (the variational flow of ε(ζ_t)).
  expect_corner_landing(0.5, Eigen::Vector3d(0.3, -0.2, -1.0), Eigen::Vector3d(0.5, -0.4, 0.3),
                        engines::event_driven::ContactMode::kSlip,
                        "cuboid on a corner, impact into slip");
}

TEST(SpatialLanding, OnACornerIntoStick) {
  // μ = 1.5 and almost no sliding before the impact: Γ > 0, the corner sticks and the cuboid
  // pivots on it.
  expect_corner_landing(1.5, Eigen::Vector3d(0.05, 0.02, -1.0), Eigen::Vector3d::Zero(),
                        engines::event_driven::ContactMode::kStick,
                        "cuboid on a corner, impact into stick");
}

TEST(SpatialLanding, FlatLandingHasNoGainAndIsRefused) {
  // Four corners at once, frictionless and inelastic. For corners i, j on one edge of the
  // bottom face the normal coupling is W_ij = 1/m + (r_i × n)ᵀ I⁻¹ (r_j × n) (r from the centre
  // of mass); the two edge neighbours j, k of a corner i have r_j + r_k = 2 r_c, with r_c the
  // bottom face's centre below the centre of mass, parallel to n, so
  // W_ij + W_ik = 2/m + (r_i × n)ᵀ I⁻¹ ((r_j + r_k) × n) = 2/m > 0 whatever the inertia: one
  // neighbour of every corner has W > 0. A perturbation that lands i first and that neighbour
  // next makes the second impact pull on i, which the engine lifts off again at a speed
  // independent of ε (OnAnEdgeWhoseCornersPullOnEachOtherIsRefused shows this for two
  // corners), while the nominal lands at rest: no flat landing of a rigid body on four corners
  // of a rectangle has a jump gain under this impact law, conewise or not, and none of the four
  // micro-event orders by the first corner can be linearised. The module refuses it.
  const SpatialScene scene(test_support::cuboid_over_ground(0.15, Eigen::Quaterniond::Identity(),
                                                            Eigen::Vector3d(0.0, 0.0, -1.0),
                                                            Eigen::Vector3d::Zero(), 0.0, 0.0));
  EventRuns runs(scene.system(), scene.model(), 0.2);
  const auto run = runs.run(scene.x0(), {});
  ASSERT_TRUE(run.succeeded()) << run.message;
  const NominalTrajectory nominal =
      nominal_from_event_run(scene.model(), scene.system(), run, {}, {}, 0.2);
  ASSERT_EQ(nominal.events.size(), 1u);
  ASSERT_EQ(nominal.events[0].micro_events.size(), 4u);

  std::vector<int> corners;
  for (const MicroEvent& me : nominal.events[0].micro_events) corners.push_back(me.contact);
  const auto& instant = first_instant(run);
  const Eigen::MatrixXd W = normal_delassus(scene, instant.q, instant.v_before, corners);
  std::vector<model::Contact<double>> contacts;
  scene.system().find_contacts(instant.q, instant.v_before, 1e3, contacts);
  const double mass = 1.0, a = 0.2, b = 0.15, h = 0.1;  // cuboid_over_ground's box
  const double Ixx = mass * (b * b + h * h) / 3, Iyy = mass * (a * a + h * h) / 3;
  const auto point = [&](int k) { return contacts.at(corners[k]).point; };
  for (int i = 0; i < 4; ++i) {
    double neighbours = 0.0;
    for (int j = 0; j < 4; ++j) {
      const Eigen::Vector3d d = point(j) - point(i);
      const bool along_x = std::abs(d.x()) > 0.1 && std::abs(d.y()) < 1e-9;
      const bool along_y = std::abs(d.y()) > 0.1 && std::abs(d.x()) < 1e-9;
      if (!along_x && !along_y) continue;
      // The closed form for a box: 1/m ± b²/I_xx ∓ a²/I_yy.
      const double expected =
          along_x ? 1 / mass + b * b / Ixx - a * a / Iyy : 1 / mass - b * b / Ixx + a * a / Iyy;
      EXPECT_NEAR(W(i, j), expected, 1e-12) << i << " " << j;
      neighbours += W(i, j);
    }
    EXPECT_NEAR(neighbours, 2 / mass, 1e-12) << "corner " << i;
  }

  expect_refused_as_order_dependent(scene, nominal, "a flat landing");
}

TEST(SpatialLanding, OnAnEdgeWhoseCornersPullOnEachOtherIsRefused) {
  // Tilted by 0.1 rad about the world x axis and spinning about it, the cuboid lands on an edge:
  // two corners at once. Their normal coupling W_01 is positive (for this box and tilt about
  // 1/m + b²/I_xx − a²/I_yy > 0), so when one corner lands first and the other after it, the
  // second impact pulls on the first (a closed contact cannot), and the engine lifts the first
  // off with ζ_f⁺ = W_fs P_s however small the perturbation: with P_f = −ζ_f/W_ff the first
  // impulse, ζ_s' = ζ_s + W_sf P_f the second corner's approach after it and
  // P_s = −ζ_s'/W_ss the second impulse (e = 0, μ = 0). The nominal lands with both corners at
  // rest, so the landing is not continuous in the initial state: no jump gain exists, conewise
  // or not, and the module refuses it.
  const SpatialScene scene(edge_landing(0.1));
  const double end = 0.035;
  EventRuns runs(scene.system(), scene.model(), end);
  const auto nominal_run = runs.run(scene.x0(), {});
  ASSERT_TRUE(nominal_run.succeeded()) << nominal_run.message;
  const NominalTrajectory nominal =
      nominal_from_event_run(scene.model(), scene.system(), nominal_run, {}, {}, end);
  ASSERT_EQ(nominal.events.size(), 1u);
  ASSERT_EQ(nominal.events[0].micro_events.size(), 2u);
  const std::vector<int> corners = {nominal.events[0].micro_events[0].contact,
                                    nominal.events[0].micro_events[1].contact};
  const auto& instant = first_instant(nominal_run);
  const Eigen::MatrixXd W = normal_delassus(scene, instant.q, instant.v_before, corners);
  const Eigen::VectorXd zeta =
      scene.model().relative_velocities(scene.model().state(instant.q, instant.v_before)).col(0);
  ASSERT_GT(W(0, 1), 0.0);

  std::vector<int> first_corners;
  for (const double sign : {1.0, -1.0}) {
    std::vector<double> errors;
    for (const double epsilon : {1e-4, 1e-5, 1e-6}) {
      const auto run = runs.run(tilted_about_y(scene, scene.x0(), sign * epsilon), {});
      ASSERT_TRUE(run.succeeded()) << run.message;
      ASSERT_EQ(run.events.size(), 3u) << "impact, impact, lift-off of the first corner";
      const auto lift_off_event = std::find_if(run.events.begin(), run.events.end(), [](auto& e) {
        return e.kind == engines::event_driven::EventKind::kLiftoff;
      });
      ASSERT_NE(lift_off_event, run.events.end());
      EXPECT_EQ(lift_off_event->key, run.events[0].key) << "the first corner lifts off";
      // The model's index of the first corner: the perturbed run's first (single) impact.
      const int first_contact =
          nominal_from_event_run(scene.model(), scene.system(), run, {}, {}, end)
              .events.at(0)
              .micro_events.at(0)
              .contact;
      const int f = first_contact == corners[0] ? 0 : 1;  // index into `corners`
      const int s = 1 - f;
      const double P_f = -zeta(corners[f]) / W(f, f);
      const double zeta_s = zeta(corners[s]) + W(s, f) * P_f;
      const double P_s = -zeta_s / W(s, s);
      const double lift_off = W(f, s) * P_s;
      errors.push_back(std::abs(lift_off_event->normal_velocity_after - lift_off));
      if (epsilon == 1e-6) {
        first_corners.push_back(f);
        std::cout << "first corner " << corners[f] << ": lift-off " << lift_off
                  << " m/s (closed form), engine at eps 1e-6 "
                  << lift_off_event->normal_velocity_after << "\n";
      }
    }
    // First-order convergence to the closed form: the error falls tenfold per decade of ε (a
    // ratio within [5, 20]: an O(ε) error with its O(ε²) remainder).
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
      EXPECT_GT(errors[k] / errors[k + 1], 5.0) << "sign " << sign << " k " << k;
      EXPECT_LT(errors[k] / errors[k + 1], 20.0) << "sign " << sign << " k " << k;
    }
  }
  ASSERT_EQ(first_corners.size(), 2u);
  EXPECT_NE(first_corners[0], first_corners[1]) << "the two tilts select the two orders";

  expect_refused_as_order_dependent(scene, nominal, "an order-dependent edge landing");
}

TEST(SpatialLanding, OnAnEdgeOverTheCentreHasTwoConesOfGains) {
  // Tilted by 0.8 rad, the landing edge lies nearly below the centre of mass and the couplings
  // of its corners are negative (the a²-terms of the turn about y dominate): the second corner's
  // impact pushes on the first, both stay closed in either order, the post-event state is the
  // same (nested projections) and the gain is conewise constant (D): one gain per order, each
  // predicting to second order the perturbations that select it.
  const SpatialScene scene(edge_landing(0.8));
  const double end = 0.035;
  EventRuns runs(scene.system(), scene.model(), end);
  const NominalTrajectory nominal = runs.nominal_from(scene.x0());
  ASSERT_EQ(nominal.events.size(), 1u);
  ASSERT_EQ(nominal.events[0].micro_events.size(), 2u);
  const TrajectorySensitivity sensitivity(scene.model(), nominal);
  const ConewiseJumpGain& event = sensitivity.events()[0];
  EXPECT_LT(event.order_dependence(), 1e-12);
  const ComposedGain first = event.gain_of_order({0, 1}), second = event.gain_of_order({1, 0});
  std::cout << "|Gz(0 first) - Gz(1 first)| = " << (first.Gz - second.Gz).lpNorm<Eigen::Infinity>()
            << " of |Gz| " << first.Gz.lpNorm<Eigen::Infinity>() << "\n";
  EXPECT_GT((first.Gz - second.Gz).lpNorm<Eigen::Infinity>(),
            1e-2 * first.Gz.lpNorm<Eigen::Infinity>());

  // The order indicator (a_0 − a_1) z(τ) is linear in z0: mirror each random direction across
  // its zero set so that both cones get the same number of directions.
  const double tau = nominal.events[0].time;
  const Eigen::RowVectorXd shift = event.micro_event({0}).gain.a - event.micro_event({1}).gain.a;
  const auto indicator = [&](const Eigen::VectorXd& z0) {
    return shift.dot(sensitivity.perturbation(z0, {}, {tau})[0]);
  };
  const int n = scene.model().state_size();
  Eigen::VectorXd normal(n);
  for (int i = 0; i < n; ++i) normal(i) = indicator(Eigen::VectorXd::Unit(n, i));
  runs.directions = 4;
  std::vector<test_support::PerturbationDirection> cone[2];
  for (const auto& d : runs.random_directions(scene.x0(), 91)) {
    test_support::PerturbationDirection mirror = d;
    mirror.z0 = d.z0 - 2 * normal.dot(d.z0) / normal.squaredNorm() * normal;
    for (const auto& candidate : {d, mirror}) {
      const std::vector<int> order =
          event.order_for(sensitivity.perturbation(candidate.z0, {}, {tau})[0], {});
      EXPECT_EQ(order[0] == 0, indicator(candidate.z0) < 0);
      cone[order[0]].push_back(candidate);
    }
  }
  ASSERT_EQ(cone[0].size(), 4u);
  ASSERT_EQ(cone[1].size(), 4u);
  runs.expect_second_order_along(scene.x0(), cone[0], "cuboid on an edge, corner 0 first");
  runs.expect_second_order_along(scene.x0(), cone[1], "cuboid on an edge, corner 1 first");

  // Positive homogeneity to round-off, and no linearity across the cones.
  const Eigen::VectorXd z0 = sensitivity.perturbation(cone[0][0].z0, {}, {tau})[0];
  const Eigen::VectorXd z1 = sensitivity.perturbation(cone[1][0].z0, {}, {tau})[0];
  const Eigen::VectorXd none;
  for (const double a : {1e-6, 0.37, 25.0, 1e4})
    EXPECT_LT((event.apply(a * z0, none) - a * event.apply(z0, none)).norm(),
              1e-12 * a * event.apply(z0, none).norm())
        << "a = " << a;
  const Eigen::VectorXd sum_of_responses = event.apply(z0, none) + event.apply(z1, none);
  EXPECT_GT((event.apply(z0 + z1, none) - sum_of_responses).norm(), 1e-2 * sum_of_responses.norm());
}
}  // namespace
}  // namespace impactbench::sensitivity
