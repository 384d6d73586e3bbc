// The CVODE session on its own: a harmonic oscillator over one period against cos/sin, the
// apex of a free parabola located as a root against v₀/g, and a guard that throws, which must
// stop the integration with the exception's message, under both root searches.
#include <cfloat>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/cvode_session.hpp"

namespace impactbench::engines::event_driven {
namespace {

using Y = Eigen::Ref<const Eigen::VectorXd>;
using Out = Eigen::Ref<Eigen::VectorXd>;
constexpr double kG = 9.81;

void no_roots(double, const Y&, Out) {}

CvodeSession::StepOutcome run_until_event(CvodeSession& session) {
  auto outcome = CvodeSession::StepOutcome::kStep;
  while (outcome == CvodeSession::StepOutcome::kStep) outcome = session.step();
  return outcome;
}

TEST(EventCvodeSession, HarmonicOscillatorOverOnePeriodToItsTolerance) {
  const double omega = 2.0 * std::numbers::pi;
  const EventDrivenOptions options;
  CvodeSession session(
      2, options,
      [&](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -omega * omega * y[0];
      },
      no_roots);
  session.restart(0.0, Eigen::Vector2d(1.0, 0.0), 0, 1.0);
  ASSERT_EQ(run_until_event(session), CvodeSession::StepOutcome::kReachedEnd);
  EXPECT_EQ(session.time(), 1.0);
  // Each step's local error is held to rtol |y_i| + atol; the flow is a rotation (in
  // (x, v/ω)), which carries earlier errors without growth, so the global error is at most
  // their sum over the steps.
  const double per_step = options.relative_tolerance * omega + options.absolute_tolerance;
  const double bound = static_cast<double>(session.steps()) * per_step;
  EXPECT_NEAR(session.state()[0], 1.0, bound);
  EXPECT_NEAR(session.state()[1], 0.0, bound);
  EXPECT_GT(session.steps(), 10);  // a real integration, not one step
}

class EventCvodeSessionRoots : public testing::TestWithParam<bool> {
 protected:
  EventDrivenOptions options() const {
    EventDrivenOptions o;
    o.dense_output_root_search = GetParam();
    return o;
  }
};

TEST_P(EventCvodeSessionRoots, FreeParabolaApexAtV0OverG) {
  // y = (h, v), ḣ = v, v̇ = −g; the guard v crosses zero downwards at the apex t* = v₀/g.
  const double v0 = 3.0;
  CvodeSession session(
      2, options(),
      [](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      [](double, const Y& y, Out g) { g[0] = y[1]; });
  session.restart(0.0, Eigen::Vector2d(1.0, v0), 1, 2.0);
  ASSERT_EQ(run_until_event(session), CvodeSession::StepOutcome::kRoot);
  EXPECT_EQ(session.roots_found().at(0), -1);
  // v is linear in t, which every order integrates and interpolates exactly: the root is off
  // by the root search's tolerance only, 100 ε (|t| + |h|) with t, h below 1.
  const double t_apex = v0 / kG;
  EXPECT_NEAR(session.time(), t_apex, 100.0 * DBL_EPSILON * 2.0);
  // The height there, to the local error control summed over the steps.
  const double bound = static_cast<double>(session.steps()) *
                       (options().relative_tolerance * 2.0 + options().absolute_tolerance);
  EXPECT_NEAR(session.state()[0], 1.0 + v0 * v0 / (2.0 * kG), bound);
}

TEST_P(EventCvodeSessionRoots, AGuardThatThrowsStopsTheIntegrationWithItsMessage) {
  CvodeSession session(
      2, options(),
      [](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      [](double t, const Y& y, Out g) {
        if (t > 0.05) throw std::runtime_error("guard exploded");
        g[0] = y[1];
      });
  session.restart(0.0, Eigen::Vector2d(1.0, 3.0), 1, 2.0);
  EXPECT_EQ(run_until_event(session), CvodeSession::StepOutcome::kFailure);
  const std::string message = session.failure_message();
  EXPECT_NE(message.find("guard exploded"), std::string::npos) << message;
  EXPECT_NE(message.find("root function failed"), std::string::npos) << message;
  EXPECT_LT(session.time(), 2.0);
}

INSTANTIATE_TEST_SUITE_P(CvodeOrOwnRootSearch, EventCvodeSessionRoots, testing::Bool());

}  // namespace
}  // namespace impactbench::engines::event_driven
