// The system instantiated on Eigen::AutoDiffScalar: seeding q with unit derivatives, the
// derivative of each contact's gap must equal its finite difference (and the analytic w_n), and
// the derivative of ζ = [w_n W_t]ᵀv along v must equal the analytic ẇ_nᵀv and Ẇ_tᵀv.
#include <cstdio>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "lib/model/planar/planar_system.hpp"
#include "lib/model/planar/planar_system_autodiff.hpp"
#include "tests/support/lib/finite_difference.hpp"

namespace impactbench::model::planar {
namespace {

using test_support::central_difference_jacobian;
using test_support::relative_error;

constexpr double kMargin = 0.1;

BodySpec body(const std::string& name, ShapeKind shape, double a, double b = 0.0) {
  BodySpec s;
  s.name = name;
  s.shape = shape;
  s.radius = a;
  s.size = {a, b, 0.0};
  return s;
}

// Ball on a block on an incline, a second ball against the block's side, a lid on the ball, a
// cap on the lid and a third ball between ball0 and the lid: every pair kind.
std::vector<BodySpec> bodies() {
  return {body("ball0", ShapeKind::kDisk, 0.3),  body("block", ShapeKind::kBox, 1.0, 0.6),
          body("ball1", ShapeKind::kDisk, 0.2),  body("lid", ShapeKind::kBox, 0.5, 0.3),
          body("ball2", ShapeKind::kDisk, 0.15), body("cap", ShapeKind::kBox, 0.4, 0.2)};
}

StaticPlaneSpec incline() {
  StaticPlaneSpec p;
  p.normal = Eigen::Vector3d(-0.2, 1.0, 0.0).normalized();
  return p;
}

TEST(PlanarAutoDiff, GapAndDriftDerivativesMatchFiniteDifferencesAndAnalyticTerms) {
  const PlanarRigidBodySystemd system(bodies(), {incline()}, 9.81, {0.4, 0.1});
  const PlanarRigidBodySystemAd system_ad(bodies(), {incline()}, 9.81, {0.4, 0.1});
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  Eigen::VectorXd q_nominal(18);
  q_nominal << 0.1, 0.92, 0.0, 0.0, 0.3, 0.2, -0.7, 0.1, 0.0, 0.1, 1.36, 0.05, 0.495, 1.136, 0.0,
      0.0875, 1.6097, 0.05;
  const int nq = static_cast<int>(q_nominal.size());

  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd q = q_nominal;
    for (int i = 0; i < nq; ++i) q(i) += jitter(rng);
    const Eigen::VectorXd v = Eigen::VectorXd::Random(nq);
    const auto features = system.detect_features(q, kMargin);
    ASSERT_GE(features.size(), 5u);

    Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> q_ad(nq), v_ad(nq);
    for (int i = 0; i < nq; ++i) {
      q_ad(i) = AutoDiff(q(i), nq, i);
      v_ad(i) = AutoDiff(v(i), Eigen::VectorXd::Zero(nq));
    }
    std::vector<Contact<AutoDiff>> ad;
    system_ad.find_contacts(q_ad, v_ad, kMargin, ad);
    std::vector<Contact<double>> plain;
    system.evaluate_features(features, q, v, plain);
    ASSERT_EQ(ad.size(), plain.size());
    if (trial == 0) {
      std::string names;
      for (const auto& c : plain) names += c.name + " ";
      std::printf("contacts: %s\n", names.c_str());
      for (const char* kind :
           {"block-ground#", "ball1-ground", "ball0-block#", "ball0-ball2", "ball2-lid#", "-lid#"})
        EXPECT_NE(names.find(kind), std::string::npos) << kind;  // every pair kind is covered
    }

    for (std::size_t k = 0; k < ad.size(); ++k) {
      ASSERT_EQ(ad[k].key, plain[k].key);
      EXPECT_NEAR(ad[k].gap.value(), plain[k].gap, 1e-14);
      const Eigen::MatrixXd fd = central_difference_jacobian(
          [&](const Eigen::VectorXd& qq) {
            std::vector<Contact<double>> out;
            system.evaluate_features(features, qq, v, out);
            return Eigen::VectorXd::Constant(1, out[k].gap);
          },
          q);
      const Eigen::VectorXd dgap = ad[k].gap.derivatives();
      EXPECT_LT(relative_error(dgap.transpose(), fd), 1e-6) << ad[k].name;
      EXPECT_LT(relative_error(dgap, plain[k].normal_direction(nq)), 1e-12) << ad[k].name;

      // d/dt ζ(q(t), v) with q̇ = v is (∂ζ/∂q) v.
      const Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> zeta = ad[k].relative_velocity(v_ad);
      EXPECT_NEAR(zeta(0).derivatives().dot(v), plain[k].normal_drift,
                  1e-12 * (1.0 + std::abs(plain[k].normal_drift)))
          << ad[k].name;
      EXPECT_NEAR(zeta(1).derivatives().dot(v), plain[k].tangent_drift(0),
                  1e-12 * (1.0 + std::abs(plain[k].tangent_drift(0))))
          << ad[k].name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 100);
}

TEST(PlanarAutoDiff, EnergyGradientIsGravityAndMomentum) {
  const PlanarRigidBodySystemAd system_ad(bodies(), {}, 9.81, {});
  const int n = 18;
  Eigen::Matrix<AutoDiff, Eigen::Dynamic, 1> q(n), v(n);
  for (int i = 0; i < n; ++i) {
    q(i) = AutoDiff(0.1 * i, 2 * n, i);
    v(i) = AutoDiff(0.3 - 0.05 * i, 2 * n, n + i);
  }
  const Eigen::VectorXd grad = system_ad.energy(q, v).derivatives();
  for (int b = 0; b < 6; ++b) {
    EXPECT_NEAR(grad(3 * b + 1), system_ad.mass(b) * 9.81, 1e-12);  // ∂E/∂y = m g
    EXPECT_NEAR(grad(n + 3 * b), system_ad.mass(b) * (0.3 - 0.05 * (3 * b)), 1e-12);  // m vx
    EXPECT_NEAR(grad(n + 3 * b + 2), system_ad.inertia(b) * (0.3 - 0.05 * (3 * b + 2)), 1e-12);
  }
}

}  // namespace
}  // namespace impactbench::model::planar
