// The flow sessions on their own, CVODE (Adams), ARKODE's explicit Runge–Kutta pair (erk) and
// our own driver of that pair (own_erk): a harmonic oscillator over one period against cos/sin,
// the apex of a free parabola located as a root against v₀/g, and a guard or a right-hand side
// that throws, which must stop the integration with the exception's message, under both root
// searches (own_erk has only the search on the dense output).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "lib/engines/event_driven/flow_session.hpp"

namespace impactbench::engines::event_driven {
namespace {

using Y = Eigen::Ref<const Eigen::VectorXd>;
using Out = Eigen::Ref<Eigen::VectorXd>;
constexpr double kG = 9.81;

void no_roots(double, const Y&, Out) {}

using Outcome = FlowSession::StepOutcome;

Outcome run_until_event(FlowSession& session) {
  auto outcome = Outcome::kStep;
  while (outcome == Outcome::kStep) outcome = session.step();
  return outcome;
}

std::string method_name(FlowMethod method) {
  switch (method) {
    case FlowMethod::kErk:
      return "Erk";
    case FlowMethod::kOwnErk:
      return "OwnErk";
    default:
      return "Adams";
  }
}

class EventFlowSession : public testing::TestWithParam<FlowMethod> {};

// The harmonic oscillator x'' = −ω² x over one period from (1, 0), against cos/sin.
// Each step's local error is held to rtol |y_i| + atol (the Runge–Kutta pair's estimate is that
// of its lower order, and it goes on with the higher); the flow is a rotation (in (x, v/ω)),
// which carries earlier errors without growth, so the global error is at most their sum over
// the steps. Returns the steps taken.
long expect_one_period_to_tolerance(const EventDrivenOptions& options) {
  const double omega = 2.0 * std::numbers::pi;
  const auto owned = make_flow_session(
      2, options,
      [&](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -omega * omega * y[0];
      },
      no_roots);
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::Vector2d(1.0, 0.0), 0, 1.0);
  EXPECT_EQ(run_until_event(session), Outcome::kReachedEnd) << session.failure_message();
  EXPECT_EQ(session.time(), 1.0);
  const double per_step = options.relative_tolerance * omega + options.absolute_tolerance;
  const double bound = static_cast<double>(session.steps()) * per_step;
  EXPECT_NEAR(session.state()[0], 1.0, bound);
  EXPECT_NEAR(session.state()[1], 0.0, bound);
  return session.steps();
}

TEST_P(EventFlowSession, HarmonicOscillatorOverOnePeriodToItsTolerance) {
  EventDrivenOptions options;
  options.method = GetParam();
  EXPECT_GT(expect_one_period_to_tolerance(options), 10);  // a real integration, not one step
}

TEST_P(EventFlowSession, ARightHandSideThatThrowsStopsTheIntegrationWithItsMessage) {
  EventDrivenOptions options;
  options.method = GetParam();
  const auto owned = make_flow_session(
      2, options,
      [](double t, const Y& y, Out ydot) {
        if (t > 0.05) throw std::runtime_error("force law exploded");
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      no_roots);
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::Vector2d(1.0, 3.0), 0, 2.0);
  EXPECT_EQ(run_until_event(session), Outcome::kFailure);
  const std::string message = session.failure_message();
  EXPECT_NE(message.find("force law exploded"), std::string::npos) << message;
}

// own_erk's dense output with Dormand–Prince is of order 4: on ẏ = t³ (y = t⁴/4, integrated
// exactly by the pair) it interpolates every step exactly, to round-off: a few roundings of
// terms below 1/4 per step, and each step's own. The same driver with Verner's pair has the
// cubic Hermite interpolant alone, which misses the quartic by h⁴ y⁗/384 inside a long step.
double largest_quartic_interpolation_error(ErkPair pair, long* steps) {
  EventDrivenOptions options;
  options.method = FlowMethod::kOwnErk;
  options.erk_pair = pair;
  options.relative_tolerance = options.absolute_tolerance = 1e-3;  // long steps
  const auto owned = make_flow_session(
      1, options, [](double t, const Y&, Out ydot) { ydot[0] = t * t * t; }, no_roots);
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::VectorXd::Zero(1), 0, 1.0);
  double error = 0.0, t_before = 0.0;
  for (auto outcome = Outcome::kStep; outcome == Outcome::kStep;) {
    outcome = session.step();
    EXPECT_NE(outcome, Outcome::kFailure) << session.failure_message();
    for (const double theta : {0.2, 0.5, 0.77}) {
      const double t = t_before + theta * (session.time() - t_before);
      error = std::max(error, std::abs(session.interpolate(t)[0] - t * t * t * t / 4.0));
    }
    t_before = session.time();
  }
  *steps = session.steps();
  return error;
}

// An own_erk session on the scalar flow ẏ = rhs, started at y(0) = 0 for t up to 1.
std::unique_ptr<FlowSession> own_erk_from_zero(FlowSession::Rhs rhs) {
  EventDrivenOptions options;
  options.method = FlowMethod::kOwnErk;
  auto session = make_flow_session(1, options, std::move(rhs), no_roots);
  session->restart(0.0, Eigen::VectorXd::Zero(1), 0, 1.0);
  return session;
}

// A right-hand side that turns NaN for good: own_erk shortens the step (a NaN may be a step
// too long), creeps up to where it fails, and stops with that cause, not with a stiffness
// advice.
TEST(EventFlowSessionOwnErk, ARightHandSideThatStaysNotFiniteStopsWithThatCause) {
  const auto owned = own_erk_from_zero([](double t, const Y&, Out ydot) {
    ydot[0] = t < 0.5 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
  });
  FlowSession& session = *owned;
  ASSERT_EQ(run_until_event(session), Outcome::kFailure);
  const std::string message = session.failure_message();
  EXPECT_NE(message.find("right-hand side is not finite just beyond"), std::string::npos)
      << message;
  EXPECT_EQ(message.find("stiff"), std::string::npos) << message;
  EXPECT_LT(session.time(), 0.5);
  EXPECT_NEAR(session.state()[0], session.time(), 1e-12);  // ẏ = 1 up to there, exactly
}

// Not finite at every t > 0: each shorter try fails too, and the 7th names the cause.
TEST(EventFlowSessionOwnErk, ARightHandSideNotFiniteRightAfterTheStartStopsAfterSevenTries) {
  const auto owned = own_erk_from_zero([](double t, const Y&, Out ydot) {
    ydot[0] = t > 0.0 ? std::numeric_limits<double>::quiet_NaN() : 1.0;
  });
  FlowSession& session = *owned;
  ASSERT_EQ(run_until_event(session), Outcome::kFailure);
  const std::string message = session.failure_message();
  EXPECT_NE(message.find("right-hand side not finite 7 times in one step"), std::string::npos)
      << message;
  EXPECT_EQ(session.steps(), 0);
}

TEST(EventFlowSessionOwnErk, DormandPrinceInterpolatesAQuarticExactly) {
  long steps = 0;
  const double error = largest_quartic_interpolation_error(ErkPair::kDormandPrince54, &steps);
  EXPECT_GT(steps, 3);
  EXPECT_LE(error, static_cast<double>(steps + 8) * DBL_EPSILON);
  EXPECT_GT(largest_quartic_interpolation_error(ErkPair::kVerner65, &steps), 1e-8);
}

TEST_P(EventFlowSession, StartsWithItsOwnFirstStepEstimateWhenGivenNone) {
  // initial_step = 0: the integrator estimates the first step; the period is then integrated
  // as accurately as with the default first step.
  EventDrivenOptions options;
  options.method = GetParam();
  options.initial_step = 0.0;
  EXPECT_GT(expect_one_period_to_tolerance(options), 10);
}

INSTANTIATE_TEST_SUITE_P(CvodeOrErk, EventFlowSession,
                         testing::Values(FlowMethod::kAdams, FlowMethod::kErk, FlowMethod::kOwnErk),
                         [](const testing::TestParamInfo<FlowMethod>& param) {
                           return method_name(param.param);
                         });

class EventFlowSessionRoots : public testing::TestWithParam<std::tuple<FlowMethod, bool>> {
 protected:
  EventDrivenOptions options() const {
    EventDrivenOptions o;
    o.method = std::get<0>(GetParam());
    o.dense_output_root_search = std::get<1>(GetParam());
    return o;
  }
};

TEST_P(EventFlowSessionRoots, FreeParabolaApexAtV0OverG) {
  // y = (h, v), ḣ = v, v̇ = −g; the guard v crosses zero downwards at the apex t* = v₀/g.
  const double v0 = 3.0;
  const auto owned = make_flow_session(
      2, options(),
      [](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      [](double, const Y& y, Out g) { g[0] = y[1]; });
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::Vector2d(1.0, v0), 1, 2.0);
  ASSERT_EQ(run_until_event(session), Outcome::kRoot);
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

TEST_P(EventFlowSessionRoots, AGuardThatThrowsStopsTheIntegrationWithItsMessage) {
  const auto owned = make_flow_session(
      2, options(),
      [](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      [](double t, const Y& y, Out g) {
        if (t > 0.05) throw std::runtime_error("guard exploded");
        g[0] = y[1];
      });
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::Vector2d(1.0, 3.0), 1, 2.0);
  EXPECT_EQ(run_until_event(session), Outcome::kFailure);
  const std::string message = session.failure_message();
  EXPECT_NE(message.find("guard exploded"), std::string::npos) << message;
  EXPECT_NE(message.find("root function failed"), std::string::npos) << message;
  EXPECT_LT(session.time(), 2.0);
}

// A guard that reaches zero and stays there (max(0, t₁ − t): an open contact's gap that an impact
// left at exactly zero): the libraries' root finding refuses to go on from its root ("root found
// at and very near t"), which the session reports as kCloseRoots, staying at the root; a restart
// there sets the guard aside and the apex, v₀/g, is found next. The search on the dense output
// sees no crossing in a guard that stays at zero and goes on to the apex by itself.
TEST_P(EventFlowSessionRoots, AGuardStuckAtZeroIsSetAsideByARestartAtItsRoot) {
  const double v0 = 3.0, t1 = 0.01;
  const auto owned = make_flow_session(
      2, options(),
      [](double, const Y& y, Out ydot) {
        ydot[0] = y[1];
        ydot[1] = -kG;
      },
      [&](double t, const Y& y, Out g) {
        g[0] = y[1];
        g[1] = std::max(0.0, t1 - t);
      });
  FlowSession& session = *owned;
  session.restart(0.0, Eigen::Vector2d(1.0, v0), 2, 2.0);
  ASSERT_EQ(run_until_event(session), Outcome::kRoot);
  EXPECT_EQ(session.roots_found().at(1), -1);
  // The guard is zero from t₁ on, so the library reports its root wherever its step ends, past
  // t₁, with the apex still ahead.
  const double t_root = session.time();
  EXPECT_GE(t_root, t1);
  EXPECT_LT(t_root, v0 / kG);
  if (!options().dense_output_root_search) {
    ASSERT_EQ(session.step(), Outcome::kCloseRoots) << session.failure_message();
    EXPECT_EQ(session.time(), t_root);
    session.restart(t_root, session.state(), 2, 2.0);
    EXPECT_EQ(session.restart_time(), t_root);
  }
  ASSERT_EQ(run_until_event(session), Outcome::kRoot) << session.failure_message();
  EXPECT_EQ(session.roots_found().at(0), -1);
  EXPECT_NEAR(session.time(), v0 / kG, 100.0 * DBL_EPSILON * 2.0);
}

INSTANTIATE_TEST_SUITE_P(CvodeOrErkAndRootSearch, EventFlowSessionRoots,
                         testing::Combine(testing::Values(FlowMethod::kAdams, FlowMethod::kErk),
                                          testing::Bool()),
                         [](const testing::TestParamInfo<std::tuple<FlowMethod, bool>>& param) {
                           return method_name(std::get<0>(param.param)) +
                                  (std::get<1>(param.param) ? "DenseOutputRoots" : "LibraryRoots");
                         });
INSTANTIATE_TEST_SUITE_P(OwnErk, EventFlowSessionRoots,
                         testing::Values(std::tuple(FlowMethod::kOwnErk, true)),
                         [](const testing::TestParamInfo<std::tuple<FlowMethod, bool>>&) {
                           return std::string("DenseOutputRoots");
                         });

}  // namespace
}  // namespace impactbench::engines::event_driven
