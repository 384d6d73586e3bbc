// The sensitivity module on nominal trajectories of the event-driven integrator
// (lib/engines/event_driven): the nominal built from a run reproduces the gains computed from
// the exact-event reference simulation, and the first-order prediction of runs of the
// event-driven integrator itself (tight tolerance) has an error shrinking like ε².
#include "lib/sensitivity/event_driven_nominal.hpp"

#include <gtest/gtest.h>

#ifdef IMPACTBENCH_HAS_EVENT_DRIVEN
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "lib/sensitivity/trajectory_sensitivity.hpp"
#include "tests/test_utilities/hybrid_reference_simulator.hpp"
#include "tests/test_utilities/sensitivity_convergence.hpp"

namespace impactbench::sensitivity {
namespace {

namespace ed = engines::event_driven;
using model::PlankBoxParameters;
using model::PlankBoxSystem;

PlankBoxParameters frictionless(double restitution) {
  PlankBoxParameters p;
  p.friction = 0.0;
  p.restitution = restitution;
  return p;
}

/// The tilted drop of sensitivity_plank_box_test: C_L lands first, 5 cm below.
Eigen::VectorXd tilted_drop() {
  const PlankBoxParameters p = frictionless(0.5);
  const double tilt = 0.15;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(8);
  x(0) = 0.5;
  x(1) = 0.5 * p.plank_thickness + 0.05 + 0.5 * p.box_length * std::sin(tilt) +
         0.5 * p.box_height * std::cos(tilt);
  x(2) = tilt;
  return x;
}

ed::EventDrivenOptions tight() {
  ed::EventDrivenOptions o;
  o.relative_tolerance = 1e-12;
  o.absolute_tolerance = 1e-12;
  o.output_interval = 0.005;
  return o;
}

class EventDrivenNominal : public ::testing::Test {
 protected:
  EventDrivenNominal()
      : system_(frictionless(0.5)), system_ad_(frictionless(0.5)), model_(system_, system_ad_) {}

  ed::EventDrivenResult run(const Eigen::VectorXd& x0, const InputFunction& u) const {
    const ed::EventDrivenIntegrator integrator(system_, tight());
    return integrator.simulate(x0.head(4), x0.tail(4), u, kEnd);
  }
  /// State at each grid time k·0.005 (samples on the grid only).
  static std::map<long, Eigen::VectorXd> grid_states(const ed::EventDrivenResult& r) {
    std::map<long, Eigen::VectorXd> out;
    for (const ed::Sample& s : r.samples) {
      const double k = std::round(s.t / 0.005);
      if (std::abs(s.t - 0.005 * k) < 1e-12) {
        Eigen::VectorXd x(8);
        x << s.q, s.v;
        out[static_cast<long>(k)] = x;
      }
    }
    return out;
  }

  static constexpr double kEnd = 0.15;
  PlankBoxSystem<double> system_;
  PlankBoxSystem<AutoDiff> system_ad_;
  MechanicalHybridModel model_;
};

TEST_F(EventDrivenNominal, SingleImpactGainsMatchTheReferenceNominal) {
  const ed::EventDrivenResult nominal_run = run(tilted_drop(), {});
  ASSERT_TRUE(nominal_run.succeeded()) << nominal_run.message;
  const NominalTrajectory nominal =
      nominal_from_event_run(model_, system_, nominal_run, {}, {}, kEnd);
  ASSERT_EQ(nominal.events.size(), 1u);
  EXPECT_EQ(nominal.events[0].micro_events[0],
            (MicroEvent{0, GuardKind::kImpact, ContactPhase::kOpen}));

  test_utilities::ReferenceOptions options;
  options.impact_phase = {ContactPhase::kOpen, ContactPhase::kOpen};
  const HybridMode open{ContactPhase::kOpen, ContactPhase::kOpen};
  const auto reference =
      test_utilities::simulate_reference(model_, open, tilted_drop(), {}, 0.0, kEnd, {}, options);
  EXPECT_NEAR(nominal.events[0].time, reference.events[0].time, 1e-9);
  const TrajectorySensitivity from_engine(model_, nominal);
  const TrajectorySensitivity from_reference(
      model_, test_utilities::nominal_from_run(reference, open, tilted_drop(), {}, {}, 0.0, kEnd));
  const Eigen::MatrixXd G1 = from_engine.events()[0].gain_of_order({0}).Gz;
  const Eigen::MatrixXd G2 = from_reference.events()[0].gain_of_order({0}).Gz;
  EXPECT_LT((G1 - G2).lpNorm<Eigen::Infinity>(), 1e-6 * G2.lpNorm<Eigen::Infinity>());
  const InputBasis none;
  EXPECT_LT((from_engine.end_point_sensitivity(none).state -
             from_reference.end_point_sensitivity(none).state)
                .lpNorm<Eigen::Infinity>(),
            1e-6);
}

TEST_F(EventDrivenNominal, PredictsPerturbedEventDrivenRunsToSecondOrder) {
  const ed::EventDrivenResult nominal_run = run(tilted_drop(), {});
  ASSERT_TRUE(nominal_run.succeeded()) << nominal_run.message;
  const NominalTrajectory nominal =
      nominal_from_event_run(model_, system_, nominal_run, {}, {}, kEnd);
  const TrajectorySensitivity sensitivity(model_, nominal);
  const double tau = nominal.events[0].time;
  const auto base = grid_states(nominal_run);
  std::vector<double> times;
  std::vector<long> keys;
  for (const auto& [k, x] : base)
    if (std::abs(0.005 * k - tau) > 0.005) {
      keys.push_back(k);
      times.push_back(0.005 * k);
    }
  test_utilities::ConvergenceSetup setup;
  setup.model = &model_;
  setup.mode0 = nominal.mode0;
  setup.x0 = tilted_drop();
  std::mt19937 rng(4);
  double lo = 1e9, hi = 0.0;
  for (int d = 0; d < 20; ++d) {
    const auto direction = test_utilities::random_direction(setup, rng);
    const auto z = sensitivity.perturbation(direction.z0, direction.input(), times);
    std::vector<double> errors;
    for (const double eps : {1e-3, 5e-4, 1e-4, 5e-5, 1e-5, 5e-6}) {
      const auto perturbed = grid_states(run(tilted_drop() + eps * direction.z0, [&](double t) {
        return Eigen::VectorXd(eps * direction.input()(t));
      }));
      double worst = 0.0;
      for (std::size_t i = 0; i < keys.size(); ++i)
        worst = std::max(
            worst,
            (perturbed.at(keys[i]) - base.at(keys[i]) - eps * z[i]).lpNorm<Eigen::Infinity>());
      errors.push_back(worst);
    }
    for (int i = 0; i < 3; ++i) {
      const double r = errors[2 * i] / errors[2 * i + 1];
      EXPECT_GE(r, 3.0) << "direction " << d;
      EXPECT_LE(r, 5.0) << "direction " << d;
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
  }
  std::cout << "[plank_box single impact, event-driven runs] error ratio e(eps)/e(eps/2), "
               "eps = 1e-3..1e-5, 20 directions: "
            << lo << " .. " << hi << "\n";
}

}  // namespace
}  // namespace impactbench::sensitivity

#else
TEST(EventDrivenNominal, NeedsTheEventDrivenEngine) {
  GTEST_SKIP() << "lib/engines/event_driven is not part of this build yet";
}
#endif
