// The [analytic] quantities of the shipped scenarios against numbers computed here by an
// independent route: flights of the bouncing ball summed one by one, the incline's force
// balance located by bisection on the scenario's own geometry and input u(t), angular
// momentum about the new corner for the rocking block, a 1-D collision simulation for the
// cradle, and a time integration of the sliding sphere.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "lib/scenario/plank_box_scenario.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::scenario {
namespace {

/// Root of f on [a, b] by bisection (f(a), f(b) of opposite signs).
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

void check_bouncing_ball(const ParameterOverrides& overrides) {
  const Scenario s = load_scenario_by_name("bouncing_ball", overrides);
  const double g = s.parameter("g"), r = s.parameter("radius"), h = s.parameter("height");
  const double e = s.parameter("restitution"), m = s.parameter("mass");
  // Flight by flight: fall from the apex, bounce with e times the speed, rise, fall again.
  double t = std::sqrt(2 * (h - r) / g);  // y(t) = h - g t^2/2 reaches r
  double v = g * t;
  double apex = h, apex_time = 0.0;
  for (int k = 0; k < 40; ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(s.analytic("impact_time", k), t, 1e-12 * (1 + t));
    EXPECT_NEAR(s.analytic("impact_speed", k), v, 1e-12 * (1 + v));
    EXPECT_NEAR(s.analytic("apex", k), apex, 1e-12);
    EXPECT_NEAR(s.analytic("apex_time", k), apex_time, 1e-12 * (1 + t));
    EXPECT_NEAR(s.analytic("flight_energy", k), m * g * apex, 1e-12 * m * g * h);
    const double rebound = e * v;
    apex = r + rebound * rebound / (2 * g);
    apex_time = t + rebound / g;
    t += 2 * rebound / g;  // y = r + rebound (t - t_k) - g (t - t_k)^2/2 returns to r
    v = rebound;
  }
  if (e < 1) {
    double t_inf = std::sqrt(2 * (h - r) / g), speed = std::sqrt(2 * g * (h - r));
    for (int k = 0; k < 20000; ++k) t_inf += 2 * (speed *= e) / g;  // the series, summed
    EXPECT_NEAR(s.analytic("t_inf"), t_inf, 1e-10);
    EXPECT_GT(s.duration, t_inf);
  }
}

TEST(Analytic, BouncingBallDefaults) {
  check_bouncing_ball({});
}
TEST(Analytic, BouncingBallOverridden) {
  check_bouncing_ball({{"height", 2.5}, {"restitution", 0.5}, {"radius", 0.2}, {"g", 3.0}});
}
TEST(Analytic, BouncingBallElastic) {
  check_bouncing_ball({{"restitution", 1.0}});
}

TEST(Analytic, SlidingBlockStopsByImpulseAndWork) {
  const Scenario s = load_scenario_by_name("sliding_block");
  const double m = s.bodies[0].mass, v0 = s.bodies[0].velocity.x();
  const double friction_force = s.material.friction * m * -s.gravity.y();
  EXPECT_NEAR(s.analytic("stop_time"), m * v0 / friction_force, 1e-15);                 // impulse
  EXPECT_NEAR(s.analytic("stop_distance"), 0.5 * m * v0 * v0 / friction_force, 1e-15);  // work
  EXPECT_NEAR(s.analytic("energy_dissipated"), 0.5 * m * v0 * v0, 1e-15);
}

TEST(Analytic, InclineSlipsWhereTheForceBalanceLeavesTheCone) {
  for (const auto& overrides :
       std::vector<ParameterOverrides>{{}, {{"angle", 10}, {"push_rate", 3}}}) {
    const Scenario s = load_scenario_by_name("incline", overrides);
    const auto& block = s.bodies[0];
    const Eigen::Vector3d n = s.planes[0].normal;
    const Eigen::Vector3d down = s.inputs[0].direction;  // unit, along the slope
    const double mu = s.material.friction, m = block.mass;
    // Applied force (gravity + push); contact force must balance it while sticking.
    const auto applied = [&](double t) {
      return Eigen::Vector3d(m * s.gravity + s.input(t)[0] * s.inputs[0].direction);
    };
    const auto excess = [&](double t) {
      const Eigen::Vector3d f = applied(t);
      return std::abs(f.dot(down)) - mu * -f.dot(n);  // |tangential| - mu normal
    };
    const double slip = bisect(excess, 0.0, s.duration);
    EXPECT_NEAR(s.analytic("slip_time"), slip, 1e-12);
    EXPECT_LT(excess(0.0), 0.0);  // sticks at first
    // After the slip: m a = applied . down - mu N, integrated with the trapezoid rule twice.
    double speed = 0.0, distance = 0.0, t = slip;
    const int steps = 200000;
    const double h = (s.duration - slip) / steps;
    const auto acceleration = [&](double time) {
      const Eigen::Vector3d f = applied(time);
      return (f.dot(down) - mu * -f.dot(n)) / m;
    };
    for (int i = 0; i < steps; ++i, t += h) {
      const double next_speed = speed + 0.5 * h * (acceleration(t) + acceleration(t + h));
      distance += 0.5 * h * (speed + next_speed);
      speed = next_speed;
    }
    EXPECT_NEAR(s.analytic("slip_acceleration"), acceleration(s.duration), 1e-10);
    EXPECT_NEAR(s.analytic("slip_speed"), speed, 1e-9);
    EXPECT_NEAR(s.analytic("slip_distance"), distance, 1e-9);
    const double alpha = std::atan2(-down.y(), -down.x());
    EXPECT_NEAR(s.analytic("incline_acceleration"),
                -s.gravity.y() * (std::sin(alpha) - mu * std::cos(alpha)), 1e-14);
  }
}

TEST(Analytic, RockingBlockRatioFromAngularMomentumAboutTheNewCorner) {
  for (const auto& overrides :
       std::vector<ParameterOverrides>{{}, {{"width", 0.5}, {"height", 1.5}, {"tilt", 8}}}) {
    const Scenario s = load_scenario_by_name("rocking_block", overrides);
    const auto& block = s.bodies[0];
    const double m = block.mass, w = block.size.x(), h = block.size.y(), g = -s.gravity.y();
    const double inertia_centre = m * (w * w + h * h) / 12.0;
    const Eigen::Vector2d centre(0.0, h / 2);  // upright, at the impact
    const Eigen::Vector2d old_corner(-w / 2, 0.0), new_corner(w / 2, 0.0);
    const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a.x() * b.y() - a.y() * b.x();
    };
    // Before: rotation omega = -1 about the old corner; v = omega x (c - old).
    const Eigen::Vector2d arm = centre - old_corner;
    const Eigen::Vector2d velocity(-(-1.0) * arm.y(), -1.0 * arm.x());
    const double momentum = inertia_centre * -1.0 + m * cross(centre - new_corner, velocity);
    const double inertia_new = inertia_centre + m * (centre - new_corner).squaredNorm();
    const double ratio = (momentum / inertia_new) / -1.0;
    EXPECT_NEAR(s.analytic("housner_ratio"), ratio, 1e-14);
    EXPECT_NEAR(s.analytic("energy_ratio"), ratio * ratio, 1e-14);
    // Energy: the centre falls from its initial height to h/2 while turning about the corner.
    const double inertia_corner = inertia_centre + m * (w * w + h * h) / 4.0;
    const double drop = block.position.y() - h / 2;
    const double omega0 = std::sqrt(2 * m * g * drop / inertia_corner);
    const auto centre_height = [&](double theta) {
      return w / 2 * std::sin(theta) + h / 2 * std::cos(theta);
    };
    const double alpha = std::atan(w / h);
    for (int k = 0; k < 10; ++k) {
      SCOPED_TRACE(k);
      EXPECT_NEAR(s.analytic("impact_omega", k), omega0 * std::pow(ratio, k), 1e-12);
      const double height = h / 2 + std::pow(ratio, 2 * k) * drop;
      const double theta = bisect([&](double a) { return centre_height(a) - height; }, 0.0, alpha);
      EXPECT_NEAR(s.analytic("amplitude", k), theta * 180 / M_PI, 1e-9);
    }
  }
}

TEST(Analytic, NewtonsCradleFromASequenceOfBinaryCollisions) {
  for (const int count : {2, 3, 5}) {
    const Scenario s = load_scenario_by_name("newtons_cradle", {{"count", count}});
    const double e = s.material.restitution;
    std::vector<double> x, v, mass;
    for (const auto& ball : s.bodies) {
      x.push_back(ball.position.x());
      v.push_back(ball.velocity.x());
      mass.push_back(ball.mass);
    }
    const double radius = s.bodies[0].radius;
    double t = 0.0;
    int impact = 0;
    for (;;) {  // next contact among neighbours approaching each other
      double next = INFINITY;
      int pair = -1;
      for (int i = 0; i + 1 < count; ++i) {
        const double closing = v[i] - v[i + 1];
        if (closing <= 0) continue;
        const double when = (x[i + 1] - x[i] - 2 * radius) / closing;
        if (when < next) next = when, pair = i;
      }
      if (pair < 0 || t + next > s.duration) break;
      for (int i = 0; i < count; ++i) x[i] += v[i] * next;
      t += next;
      EXPECT_NEAR(s.analytic("impact_time", impact), t, 1e-14);
      ++impact;
      // Newton's law for a binary impact: momentum kept, separation = e * approach.
      const double m1 = mass[pair], m2 = mass[pair + 1], v1 = v[pair], v2 = v[pair + 1];
      const double p = m1 * v1 + m2 * v2;
      v[pair] = (p - m2 * e * (v1 - v2)) / (m1 + m2);
      v[pair + 1] = (p + m1 * e * (v1 - v2)) / (m1 + m2);
    }
    for (int i = 0; i < count; ++i) x[i] += v[i] * (s.duration - t);
    EXPECT_EQ(impact, count - 1);
    EXPECT_NEAR(s.analytic("final_speed_last"), v.back(), 1e-15);
    for (int i = 0; i + 1 < count; ++i) EXPECT_NEAR(s.analytic("final_speed_others"), v[i], 1e-15);
    EXPECT_NEAR(s.analytic("last_position_end"), x.back(), 1e-13);
    double momentum = 0, energy = 0;
    for (int i = 0; i < count; ++i)
      momentum += mass[i] * v[i], energy += 0.5 * mass[i] * v[i] * v[i];
    EXPECT_NEAR(s.analytic("momentum"), momentum, 1e-15);
    EXPECT_NEAR(s.analytic("kinetic_energy"), energy, 1e-15);
  }
}

TEST(Analytic, SphereSpinMatchesAnIntegrationOfTheSlidingPhase) {
  for (const auto& overrides : std::vector<ParameterOverrides>{
           {}, {{"vx", -1}, {"vy", 2}, {"wx", 7}, {"wy", 3}, {"wz", -4}, {"friction", 0.6}}}) {
    const Scenario s = load_scenario_by_name("sphere_spin", overrides);
    const auto& ball = s.bodies[0];
    const double m = ball.mass, R = ball.radius, mu = s.material.friction, g = -s.gravity.z();
    const double inertia = 0.4 * m * R * R;
    const Eigen::Vector3d arm(0, 0, -R);  // centre to contact point
    Eigen::Vector3d v = ball.velocity, w = ball.angular_velocity, x = ball.position;
    const auto slip = [&] { return Eigen::Vector3d(v + w.cross(arm)); };
    const Eigen::Vector3d c0 = slip();
    // Explicit Euler is exact here: the forces are constant while c keeps its direction.
    const double h = 1e-6;
    double t = 0.0;
    while (slip().dot(c0) > 0) {
      const Eigen::Vector3d force = -mu * m * g * slip().normalized();
      const double step = std::min(h, slip().norm() / (3.5 * mu * g));  // do not overshoot c = 0
      x += v * step + 0.5 * force / m * step * step;
      v += force / m * step;
      w += arm.cross(force) / inertia * step;
      t += step;
      if (slip().norm() < 1e-12) break;
    }
    EXPECT_NEAR(s.analytic("slip_speed"), c0.norm(), 1e-14);
    EXPECT_NEAR(s.analytic("t_star"), t, 1e-9);
    EXPECT_NEAR(s.analytic("final_vx"), v.x(), 1e-9);
    EXPECT_NEAR(s.analytic("final_vy"), v.y(), 1e-9);
    EXPECT_NEAR(s.analytic("final_wx"), w.x(), 1e-8);
    EXPECT_NEAR(s.analytic("final_wy"), w.y(), 1e-8);
    EXPECT_NEAR(s.analytic("final_wz"), w.z(), 1e-12);
    EXPECT_NEAR(s.analytic("slip_x"), x.x() - ball.position.x(), 1e-9);
    EXPECT_NEAR(s.analytic("slip_y"), x.y() - ball.position.y(), 1e-9);
    EXPECT_NEAR(s.analytic("final_kinetic_energy"),
                0.5 * m * v.squaredNorm() + 0.5 * inertia * w.squaredNorm(), 1e-8);
  }
}

TEST(Analytic, PlankBoxInertiasByIntegrationOverTheRectangles) {
  const Scenario s = load_scenario_by_name("plank_box");
  // Simpson's rule is exact for the quadratic integrands of the second moments.
  const auto second_moment = [](double mass, double x0, double x1, double y0, double y1) {
    const int n = 10;
    const auto weight = [&](int i) { return i == 0 || i == 2 * n ? 1.0 : (i % 2 ? 4.0 : 2.0); };
    double sum = 0.0;
    for (int i = 0; i <= 2 * n; ++i)
      for (int j = 0; j <= 2 * n; ++j) {
        const double x = x0 + (x1 - x0) * i / (2 * n), y = y0 + (y1 - y0) * j / (2 * n);
        sum += weight(i) * weight(j) * (x * x + y * y);
      }
    return mass * sum / (36.0 * n * n);
  };
  const double L_B = s.parameter("L_B"), l_B = s.parameter("l_B");
  const double L_P = s.parameter("L_P"), l_P = s.parameter("l_P");
  EXPECT_NEAR(s.analytic("box_inertia"),
              second_moment(s.parameter("m_B"), -L_B / 2, L_B / 2, -l_B / 2, l_B / 2), 1e-14);
  EXPECT_NEAR(s.analytic("plank_inertia"),
              second_moment(s.parameter("m_P"), -L_P / 2, L_P / 2, -l_P / 2, l_P / 2), 1e-14);
  const double about_hinge = second_moment(s.parameter("m_P"), 0.0, L_P, -l_P / 2, l_P / 2);
  EXPECT_NEAR(s.analytic("hinge_inertia"), about_hinge, 1e-14);
  // The plank oscillates about its rest angle, where the static hinge torque k φ + c cos φ
  // (spring and weight, c = m_P g L_P/2) vanishes; its slope there is the stiffness.
  const double c = s.parameter("m_P") * s.parameter("g") * L_P / 2;
  const auto hinge_torque = [&](double phi) {
    return s.parameter("k_P") * phi + c * std::cos(phi);
  };
  const double rest = bisect(hinge_torque, -M_PI / 4, 0.0);
  EXPECT_NEAR(s.analytic("plank_equilibrium"), rest, 1e-12);
  const double slope = (hinge_torque(rest + 1e-5) - hinge_torque(rest - 1e-5)) / 2e-5;
  EXPECT_NEAR(s.analytic("plank_frequency"), std::sqrt(slope / about_hinge), 1e-8);
  // Free fall of the box's lowest corner to the plank's top surface.
  const auto& box = *s.find_body("box");
  const double start_gap = s.parameter("height");
  const double fall = bisect(
      [&](double t) { return start_gap + box.velocity.y() * t + 0.5 * s.gravity.y() * t * t; }, 0.0,
      10.0);
  EXPECT_NEAR(s.analytic("fall_time"), fall, 1e-12);
}

TEST(Analytic, PlankBoxAgreesWithTheModelParameters) {
  const Scenario s =
      load_scenario_by_name("plank_box", {{"m_P", 3.0}, {"tilt", 12.0}, {"vx", 0.5}});
  const auto p = plank_box_parameters(s);  // the model's own inertia formulas
  EXPECT_EQ(p.plank_mass, 3.0);
  EXPECT_EQ(p.friction, s.material.friction);
  EXPECT_NEAR(s.analytic("box_inertia"), p.box_inertia(), 1e-15);
  EXPECT_NEAR(s.analytic("plank_inertia"), p.plank_centre_inertia(), 1e-15);
  EXPECT_NEAR(s.analytic("hinge_inertia"), p.plank_hinge_inertia(), 1e-15);
  const auto state = plank_box_initial_state(s);
  EXPECT_NEAR(state.q[2], 12.0 * M_PI / 180.0, 1e-15);
  EXPECT_EQ(state.q[3], 0.0);
  EXPECT_EQ(state.v[0], 0.5);
  EXPECT_THROW(plank_box_parameters(load_scenario_by_name("incline")), std::invalid_argument);
}

TEST(Analytic, PileAndPyramidTotals) {
  const Scenario pile = load_scenario_by_name("disk_pile", {{"count", 37}});
  double mass = 0.0;
  for (const auto& body : pile.bodies) mass += body.mass;
  EXPECT_NEAR(pile.analytic("total_mass"), mass, 1e-12);
  EXPECT_NEAR(pile.analytic("total_weight"), mass * -pile.gravity.y(), 1e-12);
  double highest = 0.0;
  for (const auto& body : pile.bodies) highest = std::max(highest, body.position.y());
  const double pitch = 2.5 * pile.parameter("radius");
  const double rows = pile.analytic("rows");
  EXPECT_NEAR(highest, pile.parameter("lift") + pile.parameter("radius") + pitch * (rows - 1),
              0.2 * pitch);
  const Scenario pyramid = load_scenario_by_name("box_pyramid", {{"rows", 7}});
  EXPECT_EQ(pyramid.analytic("box_count"), static_cast<double>(pyramid.bodies.size()));
  EXPECT_NEAR(pyramid.analytic("total_weight"), 28 * 9.81, 1e-12);
}

}  // namespace
}  // namespace impactbench::scenario
