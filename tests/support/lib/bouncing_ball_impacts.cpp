#include "tests/support/lib/bouncing_ball_impacts.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace impactbench::test_support {

std::size_t expect_closed_form_impacts(const engines::event_driven::EventDrivenResult& result,
                                       const BallDrop& ball, double relative,
                                       std::size_t max_impacts) {
  const double g = ball.gravity, e = ball.restitution;
  double t_k = std::sqrt(2 * ball.drop_height / g), speed = std::sqrt(2 * g * ball.drop_height);
  std::size_t checked = 0, state_index = 0;
  for (const auto& event : result.events) {
    if (event.kind != engines::event_driven::EventKind::kImpact) continue;
    EXPECT_NEAR(event.t, t_k, relative * t_k) << "impact " << checked;
    while (result.event_states[state_index].t < event.t) ++state_index;
    const auto& post = result.event_states[state_index];
    const double apex = post.q[1] + post.v[1] * post.v[1] / (2 * g);
    const double apex_exact = ball.radius + (e * speed) * (e * speed) / (2 * g);
    EXPECT_NEAR(apex, apex_exact, relative * apex_exact) << "apex after impact " << checked;
    t_k += 2 * e * speed / g;
    speed *= e;
    if (++checked == max_impacts) break;
  }
  return checked;
}

}  // namespace impactbench::test_support
