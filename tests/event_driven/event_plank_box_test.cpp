// Event-driven integrator on the plank–box (source appendix F): a flat landing is one
// simultaneous impact of C_L and C_R; a tilted landing gives two impacts in order; sweeping the
// tangential approach velocity of a one-corner landing switches the impact map between stick
// and slip exactly where Γ = μ²Λ_n² − ‖Λ_t‖² (B.25, Λ the stick impulse of B.30 with
// restitution) changes sign. Γ is recomputed here from M and the contact Jacobian.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "lib/engines/event_driven/event_driven_integrator.hpp"
#include "lib/model/plank_box/plank_box_system.hpp"
#include "tests/support/lib/event_complementarity_check.hpp"

namespace impactbench::engines::event_driven {
namespace {

using model::PlankBoxParameters;
using model::PlankBoxSystem;

// The plank at rest: k φ + m_P g (L_P/2) cos φ = 0 (Newton).
double plank_equilibrium(const PlankBoxParameters& p) {
  double phi = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double f =
        p.plank_stiffness * phi + p.plank_mass * p.gravity * p.plank_length / 2 * std::cos(phi);
    const double df =
        p.plank_stiffness - p.plank_mass * p.gravity * p.plank_length / 2 * std::sin(phi);
    phi -= f / df;
  }
  return phi;
}

struct Drop {
  Eigen::VectorXd q, v;
};

// The box above the resting plank, tilted by `alpha` relative to it, its lowest corner `gap`
// above the surface, moving with world velocity (vx, vy).
Drop drop_box(const PlankBoxParameters& p, double alpha, double gap, double vx, double vy) {
  const double phi = plank_equilibrium(p);
  const Eigen::Vector2d e1(std::cos(phi), std::sin(phi)), e2(-std::sin(phi), std::cos(phi));
  // Lowest corner height above the centre, in plank axes: min over the two bottom corners.
  const double a_y = std::sin(alpha) * (-std::copysign(p.box_length / 2, alpha)) -
                     std::cos(alpha) * p.box_height / 2;
  const double y_l = p.plank_thickness / 2 + gap - a_y;
  const Eigen::Vector2d centre = 0.5 * p.plank_length * e1 + y_l * e2;
  Drop d;
  d.q = Eigen::Vector4d(centre.x(), centre.y(), phi + alpha, phi);
  d.v = Eigen::Vector4d(vx, vy, 0.0, 0.0);
  return d;
}

std::vector<Event> impacts_of(const EventDrivenResult& r) {
  std::vector<Event> out;
  for (const auto& e : r.events)
    if (e.kind == EventKind::kImpact) out.push_back(e);
  return out;
}

void expect_complementarity(const PlankBoxSystem<double>& system, const EventDrivenResult& r) {
  for (const auto& s : r.event_states)
    EXPECT_LE(test_support::acceleration_complementarity_violation(
                  system, s.q, s.v, Eigen::Vector3d::Zero(), s.modes),
              1e-9)
        << "after the event at t = " << s.t;
}

TEST(EventPlankBox, FlatLandingIsOneSimultaneousImpact) {
  PlankBoxParameters p;
  p.friction = 0.8;
  const PlankBoxSystem<double> system(p);
  const Drop d = drop_box(p, 0.0, 0.01, 0.0, -1.0);
  const auto result = EventDrivenIntegrator(system).simulate(d.q, d.v, {}, 0.2);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const auto impacts = impacts_of(result);
  ASSERT_GE(impacts.size(), 2u);
  EXPECT_EQ(impacts[0].t, impacts[1].t);
  EXPECT_NE(impacts[0].contact, impacts[1].contact);
  for (int k = 0; k < 2; ++k) {
    EXPECT_TRUE(std::isnan(impacts[k].gamma)) << "solved as one impulse-level problem";
    EXPECT_NEAR(impacts[k].normal_velocity_after, 0.0, 1e-9);
    EXPECT_GT(impacts[k].impulse_n, 0.0);
  }
  // The impulses, recomputed here from M and the contact Jacobian at the logged pre-impact
  // state: inelastic (e = 0 by default) and sticking (checked below), so ζ⁺ = 0 for n_L, n_R
  // and the tangential direction. Both corners lie on the box's bottom edge, which is parallel
  // to the plank at a flat landing, so their tangential rows coincide: only the sum of the two
  // tangential impulses is determined, and the system solved is 3 × 3 in (Λ_nL, Λ_nR, ΣΛ_t).
  ASSERT_EQ(p.restitution, 0.0);
  const EventState* at_impact = nullptr;
  for (const auto& s : result.event_states)
    if (s.t == impacts[0].t) at_impact = &s;
  ASSERT_NE(at_impact, nullptr) << "no event state at the landing";
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(at_impact->q, at_impact->v_before, 1.0, contacts);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 3);
  for (const auto& c : contacts) {
    if (c.name == "C_L") J.col(0) = c.normal_direction(4);
    if (c.name == "C_R") J.col(1) = c.normal_direction(4);
    if (c.name == "C_L") J.col(2) = c.tangent_directions(4).col(0);
  }
  ASSERT_GT(J.col(0).norm(), 0.0);
  ASSERT_GT(J.col(1).norm(), 0.0);
  const Eigen::MatrixXd M_inverse = Eigen::MatrixXd(system.mass_matrix(at_impact->q)).inverse();
  const Eigen::Vector3d impulse =
      (J.transpose() * M_inverse * J).lu().solve(-J.transpose() * at_impact->v_before);
  const Eigen::VectorXd v_after = at_impact->v_before + M_inverse * J * impulse;
  ASSERT_LE(std::abs(impulse(2)), p.friction * (impulse(0) + impulse(1))) << "not sticking";
  double engine_n_l = 0.0, engine_n_r = 0.0, engine_t = 0.0;
  for (int k = 0; k < 2; ++k) {
    (impacts[k].contact == "C_L" ? engine_n_l : engine_n_r) = impacts[k].impulse_n;
    engine_t += impacts[k].impulse_t(0);
  }
  std::printf("flat landing: impulses n_L %.9g n_R %.9g t %.3g (engine %.9g %.9g %.3g)\n",
              impulse(0), impulse(1), impulse(2), engine_n_l, engine_n_r, engine_t);
  EXPECT_NEAR(engine_n_l, impulse(0), 1e-9 * impulse(0));
  EXPECT_NEAR(engine_n_r, impulse(1), 1e-9 * impulse(1));
  EXPECT_NEAR(engine_t, impulse(2), 1e-9 * (impulse(0) + impulse(1)));
  EXPECT_LT((at_impact->v - v_after).lpNorm<Eigen::Infinity>(), 1e-9);
  expect_complementarity(system, result);
}

TEST(EventPlankBox, TiltedLandingGivesTwoOrderedImpacts) {
  PlankBoxParameters p;
  p.friction = 0.8;
  const PlankBoxSystem<double> system(p);
  const Drop d = drop_box(p, 0.05, 0.01, 0.0, -1.0);  // C_L is the lower corner
  const auto result = EventDrivenIntegrator(system).simulate(d.q, d.v, {}, 0.2);
  ASSERT_TRUE(result.succeeded()) << result.message;
  const auto impacts = impacts_of(result);
  ASSERT_GE(impacts.size(), 2u);
  EXPECT_EQ(impacts[0].contact, "C_L");
  EXPECT_EQ(impacts[1].contact, "C_R");
  EXPECT_GT(impacts[1].t, impacts[0].t + 1e-4);
  EXPECT_FALSE(std::isnan(impacts[0].gamma)) << "a single-contact impact uses Γ";
  expect_complementarity(system, result);
}

// Γ of B.25 from the pre-impact state, independently of the engine.
double gamma_of(const PlankBoxSystem<double>& system, const Eigen::VectorXd& q,
                const Eigen::VectorXd& v, const std::string& name) {
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(q, v, 1.0, contacts);
  for (const auto& c : contacts) {
    if (c.name != name) continue;
    Eigen::MatrixXd J(4, 2);
    J.col(0) = c.normal_direction(4);
    J.col(1) = c.tangent_directions(4).col(0);
    const Eigen::MatrixXd M = Eigen::MatrixXd(system.mass_matrix(q));
    const Eigen::Matrix2d D = J.transpose() * M.inverse() * J;
    Eigen::Vector2d zeta = J.transpose() * v;
    zeta[0] *= 1.0 + c.restitution;
    const Eigen::Vector2d stick = -D.inverse() * zeta;
    return c.friction * c.friction * stick[0] * stick[0] - stick[1] * stick[1];
  }
  ADD_FAILURE() << "no contact " << name;
  return 0.0;
}

TEST(EventPlankBox, ImpactMapSwitchesWhereGammaChangesSign) {
  PlankBoxParameters p;
  p.friction = 0.4;
  p.restitution = 0.3;
  const PlankBoxSystem<double> system(p);
  auto first_impact = [&](double vx, Eigen::VectorXd& q, Eigen::VectorXd& v_before) {
    const Drop d = drop_box(p, 0.05, 0.002, vx, -1.0);
    const auto result = EventDrivenIntegrator(system).simulate(d.q, d.v, {}, 0.01);
    EXPECT_TRUE(result.succeeded()) << result.message;
    const auto impacts = impacts_of(result);
    EXPECT_FALSE(impacts.empty());
    for (const auto& s : result.event_states)
      if (s.t == impacts.front().t) {
        q = s.q;
        v_before = s.v_before;
      }
    return impacts.front();
  };
  int stick = 0, slip = 0;
  double previous_gamma = 0.0, previous_vx = 0.0;
  double v_low = 0.0, v_high = 0.0;
  for (int i = 0; i <= 20; ++i) {
    const double vx = -1.0 + 0.1 * i;
    Eigen::VectorXd q, v;
    const Event e = first_impact(vx, q, v);
    ASSERT_EQ(e.contact, "C_L");
    const double gamma = gamma_of(system, q, v, "C_L");
    EXPECT_NEAR(e.gamma, gamma, 1e-9 * (1.0 + std::abs(gamma)));
    EXPECT_EQ(e.impact_map, gamma >= 0.0 ? ContactMode::kStick : ContactMode::kSlip) << "vx " << vx;
    if (e.impact_map == ContactMode::kSlip) {
      EXPECT_NEAR(std::abs(e.impulse_t[0]), p.friction * e.impulse_n, 1e-12);
    }
    (gamma >= 0.0 ? stick : slip) += 1;
    if (i > 0 && (gamma >= 0.0) != (previous_gamma >= 0.0)) {
      v_low = previous_vx;
      v_high = vx;
    }
    previous_gamma = gamma;
    previous_vx = vx;
  }
  ASSERT_GT(stick, 0);
  ASSERT_GT(slip, 0);
  // Bisect the border and check the maps on both sides of it, 1e-9 m/s apart.
  Eigen::VectorXd q, v;
  const bool low_sticks = gamma_of(system, (first_impact(v_low, q, v), q), v, "C_L") >= 0.0;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (v_low + v_high);
    first_impact(mid, q, v);
    ((gamma_of(system, q, v, "C_L") >= 0.0) == low_sticks ? v_low : v_high) = mid;
  }
  const Event below = first_impact(v_low, q, v);
  const Event above = first_impact(v_high, q, v);
  EXPECT_LT(v_high - v_low, 1e-9);
  EXPECT_EQ(below.impact_map, low_sticks ? ContactMode::kStick : ContactMode::kSlip);
  EXPECT_EQ(above.impact_map, low_sticks ? ContactMode::kSlip : ContactMode::kStick);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
