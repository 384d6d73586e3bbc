// Finite-difference checks of every planar contact quantity, for each shape pair at 100 random
// configurations in or near contact: w_n = ∂h/∂q (from the gap), W_t from the definition of the
// tangential velocity (velocities of the two material points at the contact point), and the
// acceleration terms ẇ_nᵀv = d/ds[w_n(q + s v)ᵀv], Ẇ_tᵀv = d/ds[W_t(q + s v)ᵀv].
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "lib/model/planar/planar_system.hpp"
#include "tests/support/lib/finite_difference.hpp"

namespace impactbench::model::planar {
namespace {

using test_support::central_difference_along;
using test_support::central_difference_jacobian;
using test_support::relative_error;
using System = PlanarRigidBodySystemd;

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;
constexpr double kMargin = 0.1;
constexpr int kConfigurations = 100;

BodySpec disk(const std::string& name, double radius) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::kDisk;
  b.radius = radius;
  return b;
}

BodySpec box(const std::string& name, double width, double height) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::kBox;
  b.size = {width, height, 0.0};
  return b;
}

Eigen::Matrix2d rot(double angle) {
  return (Eigen::Matrix2d() << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle))
      .finished();
}

struct Errors {
  double normal = 0.0;         ///< w_n vs ∂h/∂q
  double tangent = 0.0;        ///< W_t vs the material-point definition
  double normal_drift = 0.0;   ///< ẇ_nᵀv
  double tangent_drift = 0.0;  ///< Ẇ_tᵀv
  int contacts = 0;
  void add(double& field, double e) { field = std::max(field, e); }
};

class Checker {
 public:
  explicit Checker(std::mt19937& rng) : rng_(rng) {}

  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }

  Eigen::VectorXd random_velocity(int nv) {
    Eigen::VectorXd v(nv);
    for (int i = 0; i < nv; ++i) v(i) = uniform(-2.0, 2.0);
    return v;
  }

  /// Checks all contacts of (q, v); false when there is none or a feature changes within the
  /// finite-difference stencil (the configuration is then redrawn).
  bool check(const System& system, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
             Errors& errors) {
    const auto features = system.detect_features(q, kMargin);
    if (features.empty() || !features_stable(system, q, v, features)) return false;
    const int nv = system.num_velocities();
    std::vector<Contact<double>> contacts;
    system.evaluate_features(features, q, v, contacts);

    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const Contact<double>& c = contacts[k];
      auto frozen = [&](const Eigen::VectorXd& qq) {
        std::vector<Contact<double>> out;
        system.evaluate_features(features, qq, v, out);
        return out[k];
      };
      const Eigen::MatrixXd dh_dq = central_difference_jacobian(
          [&](const Eigen::VectorXd& qq) { return Eigen::VectorXd::Constant(1, frozen(qq).gap); },
          q, kStep);
      errors.add(errors.normal, relative_error(c.normal_direction(nv).transpose(), dh_dq));

      Eigen::VectorXd tangent_by_definition(nv);
      for (int j = 0; j < nv; ++j)
        tangent_by_definition(j) = material_tangential_velocity(c, q, Eigen::VectorXd::Unit(nv, j));
      errors.add(errors.tangent, relative_error(c.tangent_directions(nv), tangent_by_definition));

      const Eigen::VectorXd wdot_v = central_difference_along(
          [&](const Eigen::VectorXd& qq) {
            return Eigen::VectorXd::Constant(1, frozen(qq).normal_direction(nv).dot(v));
          },
          q, v, kStep);
      errors.add(errors.normal_drift,
                 relative_error(Eigen::VectorXd::Constant(1, c.normal_drift), wdot_v));
      const Eigen::VectorXd Wdot_v = central_difference_along(
          [&](const Eigen::VectorXd& qq) {
            return Eigen::VectorXd(frozen(qq).tangent_directions(nv).transpose() * v);
          },
          q, v, kStep);
      errors.add(errors.tangent_drift, relative_error(c.tangent_drift, Wdot_v));
      ++errors.contacts;
    }
    return true;
  }

 private:
  // ζ_t = tᵀ(ṗ_a − ṗ_b) for the material points of a and b at the reported contact point,
  // differentiated numerically along the rigid motion of each body.
  static double material_tangential_velocity(const Contact<double>& c, const Eigen::VectorXd& q,
                                             const Eigen::VectorXd& v) {
    const Eigen::Vector2d x = c.point.head<2>();
    const Eigen::Vector2d t(-c.normal.y(), c.normal.x());
    auto point_velocity = [&](int body) -> Eigen::Vector2d {
      if (body < 0) return Eigen::Vector2d::Zero();
      const Eigen::Vector2d centre = q.segment<2>(3 * body);
      const double angle = q(3 * body + 2);
      const Eigen::Vector2d s = rot(angle).transpose() * (x - centre);
      auto at = [&](double time) -> Eigen::Vector2d {
        return centre + time * v.segment<2>(3 * body) + rot(angle + time * v(3 * body + 2)) * s;
      };
      return test_support::central_difference(at, kStep);
    };
    return t.dot(point_velocity(c.key.body_a) - point_velocity(c.key.body_b));
  }

  static bool same_keys(const std::vector<ContactFeature>& a,
                        const std::vector<ContactFeature>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].key != b[i].key) return false;
    return true;
  }

  static bool features_stable(const System& system, const Eigen::VectorXd& q,
                              const Eigen::VectorXd& v,
                              const std::vector<ContactFeature>& nominal) {
    std::vector<Eigen::VectorXd> directions = {v};
    for (int j = 0; j < q.size(); ++j) directions.push_back(Eigen::VectorXd::Unit(q.size(), j));
    for (const auto& d : directions)
      for (double sign : {-1.0, 1.0})
        if (!same_keys(system.detect_features(Eigen::VectorXd(q + sign * 2.0 * kStep * d), kMargin),
                       nominal))
          return false;
    return true;
  }

  std::mt19937& rng_;
};

/// Draws configurations with `make` until kConfigurations of them have contacts with stable
/// features; asserts the finite-difference agreement over all of them.
void run_pair(const std::function<bool(Checker&, Errors&)>& draw_and_check, unsigned seed) {
  std::mt19937 rng(seed);
  Checker checker(rng);
  Errors errors;
  int accepted = 0;
  int attempts = 0;
  while (accepted < kConfigurations) {
    ASSERT_LT(++attempts, 200 * kConfigurations) << "too few configurations in contact";
    if (draw_and_check(checker, errors)) ++accepted;
  }
  EXPECT_GE(errors.contacts, kConfigurations);
  EXPECT_LT(errors.normal, kTolerance) << "w_n vs dh/dq";
  EXPECT_LT(errors.tangent, kTolerance) << "W_t vs material-point velocity";
  EXPECT_LT(errors.normal_drift, kTolerance) << "wdot_n^T v";
  EXPECT_LT(errors.tangent_drift, kTolerance) << "Wdot_t^T v";
  std::printf(
      "contacts %d (attempts %d): max rel. errors w_n %.2e, W_t %.2e, wdot_n'v %.2e, Wdot_t'v "
      "%.2e\n",
      errors.contacts, attempts, errors.normal, errors.tangent, errors.normal_drift,
      errors.tangent_drift);
  ::testing::Test::RecordProperty("contacts", errors.contacts);
  ::testing::Test::RecordProperty("attempts", attempts);
}

StaticPlaneSpec inclined_line(Checker& r, double& angle) {
  angle = r.uniform(-0.6, 0.6);
  StaticPlaneSpec plane;
  plane.point = {r.uniform(-1.0, 1.0), r.uniform(-1.0, 1.0), 0.0};
  plane.normal = {-std::sin(angle), std::cos(angle), 0.0};
  return plane;
}

TEST(PlanarContacts, DiskGroundDerivativesMatchFiniteDifferences) {
  run_pair(
      [](Checker& r, Errors& errors) {
        double slope = 0.0;
        const StaticPlaneSpec plane = inclined_line(r, slope);
        const double radius = r.uniform(0.1, 0.5);
        const Eigen::Vector3d tangent(std::cos(slope), std::sin(slope), 0.0);
        BodySpec ball = disk("ball", radius);
        const System system({ball}, {plane}, 9.81, {});
        const Eigen::Vector3d centre = plane.point + r.uniform(-1.0, 1.0) * tangent +
                                       (radius + r.uniform(-0.02, 0.05)) * plane.normal;
        const Eigen::VectorXd q = Eigen::Vector3d(centre.x(), centre.y(), r.uniform(-3.0, 3.0));
        return r.check(system, q, r.random_velocity(3), errors);
      },
      1);
}

TEST(PlanarContacts, BoxInclinedGroundDerivativesMatchFiniteDifferences) {
  run_pair(
      [](Checker& r, Errors& errors) {
        double slope = 0.0;
        const StaticPlaneSpec plane = inclined_line(r, slope);
        const System system({box("block", r.uniform(0.2, 1.0), r.uniform(0.2, 1.0))}, {plane}, 9.81,
                            {});
        const double angle = r.uniform(-3.0, 3.0);
        const Eigen::Vector2d n = plane.normal.head<2>();
        double lowest = 1e9;  // lowest corner height above the line for a centre on the line
        for (const auto& corner : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                   Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)}) {
          const Eigen::Vector2d s = 0.5 * corner.cwiseProduct(system.body(0).size.head<2>());
          lowest = std::min(lowest, n.dot(rot(angle) * s));
        }
        const Eigen::Vector2d centre = plane.point.head<2>() +
                                       r.uniform(-1.0, 1.0) * Eigen::Vector2d(n.y(), -n.x()) +
                                       (r.uniform(-0.02, 0.05) - lowest) * n;
        const Eigen::VectorXd q = Eigen::Vector3d(centre.x(), centre.y(), angle);
        return r.check(system, q, r.random_velocity(3), errors);
      },
      2);
}

TEST(PlanarContacts, DiskDiskDerivativesMatchFiniteDifferences) {
  run_pair(
      [](Checker& r, Errors& errors) {
        const double ra = r.uniform(0.1, 0.5);
        const double rb = r.uniform(0.1, 0.5);
        const System system({disk("ball0", ra), disk("ball1", rb)}, {}, 9.81, {});
        const double direction = r.uniform(-M_PI, M_PI);
        const double distance = ra + rb + r.uniform(-0.05, 0.05);
        Eigen::VectorXd q(6);
        q << r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-3, 3), 0, 0, r.uniform(-3, 3);
        q.segment<2>(3) =
            q.head<2>() + distance * Eigen::Vector2d(std::cos(direction), std::sin(direction));
        return r.check(system, q, r.random_velocity(6), errors);
      },
      3);
}

TEST(PlanarContacts, DiskBoxDerivativesMatchFiniteDifferencesForFacesVerticesAndInside) {
  int face_outside = 0;
  int face_inside = 0;
  int vertex = 0;
  run_pair(
      [&](Checker& r, Errors& errors) {
        const double radius = r.uniform(0.1, 0.3);
        const double w = r.uniform(0.4, 1.0);
        const double h = r.uniform(0.4, 1.0);
        const System system({disk("ball", radius), box("block", w, h)}, {}, 9.81, {});
        const double angle = r.uniform(-3, 3);
        const Eigen::Vector2d box_centre(r.uniform(-1, 1), r.uniform(-1, 1));
        const Eigen::Vector2d local(r.uniform(-0.5 * w - radius - 0.05, 0.5 * w + radius + 0.05),
                                    r.uniform(-0.5 * h - radius - 0.05, 0.5 * h + radius + 0.05));
        const Eigen::Vector2d centre = box_centre + rot(angle) * local;
        Eigen::VectorXd q(6);
        q << centre, r.uniform(-3, 3), box_centre, angle;
        if (!r.check(system, q, r.random_velocity(6), errors)) return false;
        const auto features = system.detect_features(q, kMargin);
        EXPECT_EQ(features.size(), 1u);
        const bool inside = (local.cwiseAbs() - Eigen::Vector2d(0.5 * w, 0.5 * h)).maxCoeff() < 0;
        if (features[0].key.feature >= 4)
          ++vertex;
        else if (inside)
          ++face_inside;
        else
          ++face_outside;
        return true;
      },
      4);
  EXPECT_GT(face_outside, 10);
  EXPECT_GT(face_inside, 10);
  EXPECT_GT(vertex, 10);
}

TEST(PlanarContacts, BoxBoxDerivativesMatchFiniteDifferencesForClippedManifolds) {
  int clipped_points = 0;
  int two_point_manifolds = 0;
  run_pair(
      [&](Checker& r, Errors& errors) {
        const System system({box("box0", r.uniform(0.3, 1.0), r.uniform(0.3, 1.0)),
                             box("box1", r.uniform(0.3, 1.0), r.uniform(0.3, 1.0))},
                            {}, 9.81, {});
        const double reach =
            0.5 * (system.body(0).size.head<2>().norm() + system.body(1).size.head<2>().norm());
        const double direction = r.uniform(-M_PI, M_PI);
        const double distance = r.uniform(0.4, 1.0) * reach;
        Eigen::VectorXd q(6);
        q << r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-3, 3), 0, 0, r.uniform(-3, 3);
        q.segment<2>(3) =
            q.head<2>() + distance * Eigen::Vector2d(std::cos(direction), std::sin(direction));
        // A flat face on a flat face half the time, the case that produces two clipped points.
        if (r.uniform(0, 1) < 0.5)
          q(5) = q(2) + 0.5 * M_PI * std::round(r.uniform(-2, 2)) + r.uniform(-0.05, 0.05);
        if (!r.check(system, q, r.random_velocity(6), errors)) return false;
        const auto features = system.detect_features(q, kMargin);
        if (features.size() == 2) ++two_point_manifolds;
        for (const auto& f : features) {
          const BodySpec& inc = system.body(f.key.body_a);
          const Eigen::Vector2d corner = 0.5 * inc.size.head<2>();
          if ((f.s_a.cwiseAbs() - corner).cwiseAbs().minCoeff() < 1e-12 &&
              (f.s_a.cwiseAbs() - corner).cwiseAbs().maxCoeff() > 1e-9)
            ++clipped_points;  // on an edge, not at a vertex
        }
        return true;
      },
      5);
  EXPECT_GT(clipped_points, 10);
  EXPECT_GT(two_point_manifolds, 10);
}

TEST(PlanarContacts, NormalsPointToBodyAAndTangentIsNormalRotatedPlus90) {
  const System system({disk("ball", 0.5), box("block", 1.0, 1.0)}, {StaticPlaneSpec{}}, 9.81, {});
  Eigen::VectorXd q(6);
  q << 0.0, 1.40, 0.0, 0.0, 0.45, 0.0;  // ball resting on block resting on the ground
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, Eigen::VectorXd::Zero(6), 0.0, contacts);
  ASSERT_EQ(contacts.size(), 3u);  // block corners 0 and 1 on the ground, ball on the top face
  for (const auto& c : contacts) {
    EXPECT_NEAR(c.normal.y(), 1.0, 1e-15) << c.name;
    EXPECT_NEAR(c.gap, -0.05, 1e-12) << c.name;  // both overlap by 5 cm
    const Eigen::MatrixXd W = c.tangent_directions(6);
    EXPECT_NEAR(W(3 * c.key.body_a, 0), -1.0, 1e-15) << c.name;  // t = n rotated by +90° = −x
  }
  EXPECT_EQ(contacts[0].name, "block-ground#0");
  EXPECT_EQ(contacts[1].name, "block-ground#1");
  EXPECT_EQ(contacts[2].name, "ball-block#2");
  EXPECT_EQ(contacts[2].key, (ContactKey{0, 1, 2}));
}

}  // namespace
}  // namespace impactbench::model::planar
