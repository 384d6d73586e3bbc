// The single-contact impact map on a box corner, whose Delassus matrix couples normal and
// tangent (D_nt ≠ 0): the normal impulse alone would make the corner slide. The post-impact
// velocity must be the impulse-level Coulomb solution, found here independently by enumerating
// the three planar candidates (stick, slip in +t, slip in −t) and keeping the consistent one.
// The text's B.21 direction ε(ζ_t⁻) is shown to violate the friction law when a tiny
// pre-impact sliding points the other way (the defect that made the plank–box landing differ
// from Moreau–Jean).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "lib/engines/event_driven/impact_map.hpp"
#include "tests/support/lib/analytic_test_systems.hpp"

namespace impactbench::engines::event_driven {
namespace {

struct Candidate {
  Eigen::Vector2d impulse;  // (Λ_n, Λ_t)
  Eigen::Vector2d after;    // (ζ_n⁺, ζ_t⁺)
};

// Impulse-level Coulomb law with Newton restitution on the normal: u = D Λ + ζ⁻ + (e ζ_n⁻, 0).
Candidate coulomb_by_enumeration(const Eigen::Matrix2d& D, const Eigen::Vector2d& zeta, double mu,
                                 double e) {
  const Eigen::Vector2d q(zeta[0] * (1.0 + e), zeta[1]);
  std::vector<Candidate> consistent;
  const Eigen::Vector2d stick = D.lu().solve(-q);
  if (stick[0] >= 0.0 && std::abs(stick[1]) <= mu * stick[0])
    consistent.push_back({stick, D * stick + zeta});
  for (const double sigma : {1.0, -1.0}) {  // Λ_t = σ μ Λ_n
    const double lambda_n = -q[0] / (D(0, 0) + sigma * mu * D(0, 1));
    const Eigen::Vector2d impulse(lambda_n, sigma * mu * lambda_n);
    const Eigen::Vector2d after = D * impulse + zeta;
    if (lambda_n >= 0.0 && sigma * after[1] < 0.0) consistent.push_back({impulse, after});
  }
  EXPECT_EQ(consistent.size(), 1u) << "the planar impulse-level problem has one solution here";
  return consistent.front();
}

TEST(EventImpactMap, BoxCornerImpactFollowsTheImpulseLevelCoulombLaw) {
  const double mu = 0.5;
  const test_support::PlanarTestWorld box({{"box", 1.0, 0.0, 0.2, 0.1}}, 9.81, mu, 0.0);
  const Eigen::Vector3d q(0.0, 0.05, 0.0);  // resting height: both bottom corners touch
  std::vector<model::Contact<double>> contacts;
  box.find_contacts(q, Eigen::Vector3d::Zero(), 1e-9, contacts);
  ASSERT_EQ(contacts.size(), 2u);
  const model::Contact<double>& corner = contacts[0];  // corner 0: (−w/2, −h/2), bottom left
  const EventDrivenOptions options;
  int b21_violations = 0;
  for (const double e : {0.0, 0.5}) {
    for (const double vx : {-0.3, -1e-3, 0.0, 1e-3, 0.3}) {
      const Eigen::Vector3d v_minus(vx, -1.62, 0.0);
      const DynamicsAtState dynamics(box, q, v_minus, Eigen::VectorXd(0));
      const ContactFrame frame = ContactFrame::of(corner, 3);
      const Eigen::Matrix2d D = frame.J.transpose() * dynamics.solve(frame.J);
      const Eigen::Vector2d zeta = frame.J.transpose() * v_minus;
      const Candidate expected = coulomb_by_enumeration(D, zeta, mu, e);

      const ImpactResult impact = single_contact_impact(dynamics, v_minus, corner, e, options);
      ASSERT_TRUE(impact.ok) << impact.message;
      const ContactImpulse& c = impact.contacts.front();
      EXPECT_NEAR((c.impulse - expected.impulse).norm(), 0.0, 1e-12) << "vx " << vx << " e " << e;
      EXPECT_NEAR(c.zeta_after[0], -e * zeta[0], 1e-12);
      // Maximum dissipation: friction never pushes along the post-impact sliding.
      EXPECT_LE(c.impulse[1] * c.zeta_after[1], 1e-15) << "vx " << vx << " e " << e;

      // B.21's direction, friction against the pre-impact sliding, for comparison.
      if (zeta[1] != 0.0 && c.map == ContactMode::kSlip) {
        const double sigma = -std::copysign(1.0, zeta[1]);
        const double lambda_n = -(1.0 + e) * zeta[0] / (D(0, 0) + sigma * mu * D(0, 1));
        const double zeta_t_after = D(1, 0) * lambda_n + D(1, 1) * sigma * mu * lambda_n + zeta[1];
        if (sigma * zeta_t_after > 0.0) {
          ++b21_violations;
          std::printf("B.21 violates Coulomb at vx = %g, e = %g\n", vx, e);
        }
      }
    }
  }
  // The impulse reverses the +x pre-impact sliding at vx = 1e-3 (both e) and, with e = 0.5 and
  // its larger normal impulse, at vx = 0.3 too: there B.21 pushes the corner along its
  // post-impact sliding.
  EXPECT_EQ(b21_violations, 3);
}

}  // namespace
}  // namespace impactbench::engines::event_driven
