#pragma once
// The bouncing ball's closed form, checked on an event-driven run: a ball of radius r dropped
// with its centre h0 above contact height under gravity g, restitution e, hits at
//   t_1 = √(2 h0 / g),  t_{k+1} = t_k + 2 e v_k / g,  v_1 = √(2 g h0),  v_{k+1} = e v_k,
// and after impact k its centre rises to r + (e v_k)² / (2 g) (its apex from the post-impact
// state). Each impact time and apex must agree to `relative` of its value.
#include <cstddef>

#include "lib/engines/event_driven/event_driven_integrator.hpp"

namespace impactbench::test_support {

struct BallDrop {
  double radius = 0.1;
  double drop_height = 0.9;  ///< h0: centre height above its contact height at release [m]
  double restitution = 0.9;
  double gravity = 9.81;
};

/// Checks the first `max_impacts` impacts of `result` (all when 0) with gtest expectations;
/// returns how many were checked.
std::size_t expect_closed_form_impacts(const engines::event_driven::EventDrivenResult& result,
                                       const BallDrop& ball, double relative,
                                       std::size_t max_impacts = 0);

}  // namespace impactbench::test_support
