// Contact kinematics of the spatial model: every pair type at 100 random configurations checked
// against central finite differences, and the broad phase against brute force on a real pile.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"
#include "tests/support/lib/finite_difference.hpp"
#include "tests/support/lib/random_poses.hpp"

namespace impactbench::model::spatial {
namespace {

using System = SpatialRigidBodySystem<double>;
using test_support::central_difference;
using test_support::random_unit_quaternion;
using test_support::random_vector;

constexpr double kAllContacts = 1e3;  // margin [m] that returns every candidate of a small scene
constexpr double kEps = 1e-6;         // FD step
constexpr double kRelTol = 1e-6;

BodySpec sphere(const std::string& name, double radius, double mass = 1.3) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::kSphere;
  b.radius = radius;
  b.mass = mass;
  return b;
}

BodySpec cuboid(const std::string& name, const Eigen::Vector3d& size, double mass = 2.1) {
  BodySpec b;
  b.name = name;
  b.shape = ShapeKind::kCuboid;
  b.size = size;
  b.mass = mass;
  return b;
}

StaticPlaneSpec plane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  StaticPlaneSpec p;
  p.name = "ground";
  p.point = point;
  p.normal = normal;
  return p;
}

const Contact<double>& contact_with_key(const std::vector<Contact<double>>& contacts,
                                        const ContactKey& key) {
  const auto it = std::find_if(contacts.begin(), contacts.end(),
                               [&](const Contact<double>& c) { return c.key == key; });
  if (it == contacts.end()) throw std::runtime_error("contact lost under perturbation");
  return *it;
}

// Largest |fd − analytic| / max(1, |analytic|) seen, printed per test for the record.
double worst_relative_error = 0.0;

bool near(double fd, double analytic) {
  const double relative = std::abs(fd - analytic) / std::max(1.0, std::abs(analytic));
  worst_relative_error = std::max(worst_relative_error, relative);
  return relative <= kRelTol;
}

class SpatialContacts : public ::testing::Test {
 protected:
  void SetUp() override { worst_relative_error = 0.0; }
  void TearDown() override { std::printf("worst FD relative error: %.3g\n", worst_relative_error); }
};

// World position at pose q of the material point of `body` that sits at `point` in pose q0.
Eigen::Vector3d material_point(const Eigen::VectorXd& q0, const Eigen::VectorXd& q, int body,
                               const Eigen::Vector3d& point) {
  if (body < 0) return point;  // static environment
  const auto rotation = [&](const Eigen::VectorXd& x) {
    const Eigen::Vector4d c = x.segment<4>(7 * body + 3);
    return Eigen::Quaterniond(c(0), c(1), c(2), c(3)).toRotationMatrix();
  };
  const Eigen::Vector3d local = rotation(q0).transpose() * (point - q0.segment<3>(7 * body));
  return q.segment<3>(7 * body) + rotation(q) * local;
}

// Checks every contact of (q, v) against central differences:
//  - w_nᵀ δv = d/dε h(q ⊕ ε δv),
//  - W_tᵀ δv = d/dε t_kᵀ (c_a(ε) − c_b(ε)) with c_a, c_b the material witness points,
//  - ẇ_nᵀ v, Ẇ_tᵀ v = d/dε [w_n W_t](q ⊕ ε v)ᵀ v,
// and that (n, t1, t2) is a right-handed orthonormal frame. Returns the number of contacts.
int check_contacts(const System& system, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                   std::mt19937& rng) {
  std::vector<Contact<double>> contacts, perturbed;
  system.find_contacts(q, v, kAllContacts, contacts);
  const int nv = system.num_velocities();
  for (const Contact<double>& c : contacts) {
    SCOPED_TRACE(c.name);
    const Eigen::Vector3d n = c.blocks[0].rows.row(0).head<3>().transpose();
    const Eigen::Vector3d t1 = c.blocks[0].rows.row(1).head<3>().transpose();
    const Eigen::Vector3d t2 = c.blocks[0].rows.row(2).head<3>().transpose();
    EXPECT_LT((n - c.normal).norm(), 1e-14);
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    EXPECT_LT(std::abs(n.dot(t1)) + std::abs(n.dot(t2)) + std::abs(t1.dot(t2)), 1e-14);
    EXPECT_LT((t1.cross(t2) - n).norm(), 1e-14);

    const Eigen::Vector3d witness_a = c.point;
    const Eigen::Vector3d witness_b = c.point - c.gap * c.normal;
    Eigen::VectorXd dv(nv);
    for (int i = 0; i < nv; ++i) dv(i) = random_vector(rng, 1.0)(0);
    const auto at = [&](double e) { return system.integrate_position(q, dv, e); };

    const double gap_rate = central_difference(
        [&](double e) {
          system.find_contacts(at(e), v, kAllContacts, perturbed);
          return contact_with_key(perturbed, c.key).gap;
        },
        kEps);
    const Eigen::VectorXd zeta = c.relative_velocity(dv);
    EXPECT_PRED2(near, gap_rate, zeta(0)) << "w_n";
    EXPECT_PRED2(near, gap_rate, c.normal_direction(nv).dot(dv)) << "dense w_n";

    const Eigen::VectorXd slip = central_difference(
        [&](double e) -> Eigen::VectorXd {
          const Eigen::VectorXd qe = at(e);
          const Eigen::Vector3d d = material_point(q, qe, c.key.body_a, witness_a) -
                                    material_point(q, qe, c.key.body_b, witness_b);
          return Eigen::Vector3d(n.dot(d), t1.dot(d), t2.dot(d));
        },
        kEps);
    for (int k = 0; k < 3; ++k) EXPECT_PRED2(near, slip(k), zeta(k)) << "material row " << k;
    EXPECT_LT((c.tangent_directions(nv).transpose() * dv - zeta.tail<2>()).norm(), 1e-14);

    const Eigen::VectorXd drift = central_difference(
        [&](double e) -> Eigen::VectorXd {
          system.find_contacts(system.integrate_position(q, v, e), v, kAllContacts, perturbed);
          return contact_with_key(perturbed, c.key).relative_velocity(v);
        },
        kEps);
    EXPECT_PRED2(near, drift(0), c.normal_drift) << "normal drift";
    EXPECT_PRED2(near, drift(1), c.tangent_drift(0)) << "tangent drift 1";
    EXPECT_PRED2(near, drift(2), c.tangent_drift(1)) << "tangent drift 2";
  }
  return static_cast<int>(contacts.size());
}

Eigen::VectorXd random_velocities(int bodies, std::mt19937& rng) {
  Eigen::VectorXd v(6 * bodies);
  for (int i = 0; i < bodies; ++i)
    v.segment<6>(6 * i) << random_vector(rng, 2.0), random_vector(rng, 3.0);
  return v;
}

Eigen::Vector3d random_tilted_normal(std::mt19937& rng) {
  Eigen::Vector3d n = random_vector(rng, 1.0);
  n.z() = std::abs(n.z()) + 0.3;
  return n.normalized();
}

TEST_F(SpatialContacts, SphereOnTiltedPlaneMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> radius(0.1, 1.0), gap(-0.05, 0.05);
  for (int config = 0; config < 100; ++config) {
    const double r = radius(rng), h = gap(rng);
    const Eigen::Vector3d n = random_tilted_normal(rng), x0 = random_vector(rng, 1.0);
    SpatialSystemSpec spec;
    spec.bodies = {sphere("ball", r)};
    spec.planes = {plane(x0, n)};
    const System system(spec);
    Eigen::Vector3d along = random_vector(rng, 1.0);
    along -= n * n.dot(along);
    Eigen::VectorXd q(7);
    q << x0 + along + (r + h) * n, random_unit_quaternion(rng);
    std::vector<Contact<double>> contacts;
    system.find_contacts(q, random_velocities(1, rng), kAllContacts, contacts);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].gap, h, 1e-14);
    EXPECT_EQ(contacts[0].name, "ball-ground");
    EXPECT_EQ(check_contacts(system, q, random_velocities(1, rng), rng), 1);
  }
}

TEST_F(SpatialContacts, SphereSphereMatchesFiniteDifferences) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> radius(0.1, 1.0), gap(-0.05, 0.05);
  for (int config = 0; config < 100; ++config) {
    const double ra = radius(rng), rb = radius(rng), h = gap(rng);
    SpatialSystemSpec spec;
    spec.bodies = {sphere("a", ra), sphere("b", rb)};
    const System system(spec);
    const Eigen::Vector3d pb = random_vector(rng, 1.0);
    const Eigen::Vector3d dir = random_vector(rng, 1.0).normalized();  // all of the sphere
    Eigen::VectorXd q(14);
    q << pb + (ra + rb + h) * dir, random_unit_quaternion(rng), pb, random_unit_quaternion(rng);
    std::vector<Contact<double>> contacts;
    system.find_contacts(q, random_velocities(2, rng), kAllContacts, contacts);
    ASSERT_EQ(contacts.size(), 1u);
    EXPECT_NEAR(contacts[0].gap, h, 1e-14);
    EXPECT_LT((contacts[0].normal - dir).norm(), 1e-14);
    EXPECT_LT((contacts[0].point - (pb + rb * dir + h * dir)).norm(), 1e-14);
    EXPECT_EQ(check_contacts(system, q, random_velocities(2, rng), rng), 1);
  }
}

TEST_F(SpatialContacts, BoxCornersOnTiltedPlaneMatchFiniteDifferences) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> side(0.1, 1.0), height(-0.2, 0.5);
  for (int config = 0; config < 100; ++config) {
    const Eigen::Vector3d size(side(rng), side(rng), side(rng));
    const Eigen::Vector3d n = random_tilted_normal(rng), x0 = random_vector(rng, 1.0);
    SpatialSystemSpec spec;
    spec.bodies = {cuboid("box", size)};
    spec.planes = {plane(x0, n)};
    const System system(spec);
    Eigen::VectorXd q(7);
    q << x0 + height(rng) * n + random_vector(rng, 0.5), random_unit_quaternion(rng);
    // Independent gaps: corners from Eigen's quaternion.
    const Eigen::Quaterniond o(q(3), q(4), q(5), q(6));
    std::vector<Contact<double>> contacts;
    system.find_contacts(q, random_velocities(1, rng), kAllContacts, contacts);
    ASSERT_EQ(contacts.size(), 8u);
    for (const Contact<double>& c : contacts) {
      const int k = c.key.feature;
      const Eigen::Vector3d local(k & 1 ? 0.5 * size.x() : -0.5 * size.x(),
                                  k & 2 ? 0.5 * size.y() : -0.5 * size.y(),
                                  k & 4 ? 0.5 * size.z() : -0.5 * size.z());
      const Eigen::Vector3d corner = q.head<3>() + o * local;
      EXPECT_NEAR(c.gap, n.dot(corner - x0), 1e-14);
      EXPECT_LT((c.point - corner).norm(), 1e-14);
      EXPECT_EQ(c.name, "box-ground#" + std::to_string(k));
    }
    EXPECT_EQ(check_contacts(system, q, random_velocities(1, rng), rng), 8);
  }
}

// Distance from a point to a box given by centre, orientation and half extents, negative inside.
double signed_distance_to_box(const Eigen::Vector3d& x, const Eigen::Vector3d& centre,
                              const Eigen::Quaterniond& o, const Eigen::Vector3d& half) {
  const Eigen::Vector3d local = o.conjugate() * (x - centre);
  const Eigen::Vector3d excess = local.cwiseAbs() - half;
  if ((excess.array() <= 0).all()) return excess.maxCoeff();
  return excess.cwiseMax(0.0).norm();
}

TEST_F(SpatialContacts, SphereBoxMatchesFiniteDifferencesInsideAndOutside) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> side(0.2, 1.0), radius(0.05, 0.5), unit(-1.0, 1.0);
  int inside = 0, outside = 0;
  for (int config = 0; config < 100; ++config) {
    const Eigen::Vector3d size(side(rng), side(rng), side(rng));
    const double r = radius(rng);
    const bool sphere_first = config % 3 == 0;  // the key names the sphere first either way
    SpatialSystemSpec spec;
    spec.bodies = {cuboid("box", size), sphere("ball", r)};
    if (sphere_first) std::swap(spec.bodies[0], spec.bodies[1]);
    const int box = sphere_first ? 1 : 0, ball = 1 - box;
    const System system(spec);

    const Eigen::Vector4d quat = random_unit_quaternion(rng);
    const Eigen::Quaterniond o(quat(0), quat(1), quat(2), quat(3));
    const Eigen::Vector3d centre = random_vector(rng, 1.0);
    // Even configurations put the centre inside the box, odd ones outside within 0.3 m.
    Eigen::Vector3d local;
    do {
      const double reach = config % 2 == 0 ? 0.95 : 1.0 + 0.6 / size.minCoeff();
      local = 0.5 * reach *
              Eigen::Vector3d(unit(rng) * size.x(), unit(rng) * size.y(), unit(rng) * size.z());
    } while ((config % 2 == 1) == ((local.cwiseAbs() - 0.5 * size).array() <= 0).all());
    Eigen::VectorXd q(14);
    q.segment<3>(7 * box) = centre;
    q.segment<4>(7 * box + 3) = quat;
    q.segment<3>(7 * ball) = centre + o * local;
    q.segment<4>(7 * ball + 3) = random_unit_quaternion(rng);

    std::vector<Contact<double>> contacts;
    system.find_contacts(q, random_velocities(2, rng), kAllContacts, contacts);
    ASSERT_EQ(contacts.size(), 1u);
    const Contact<double>& c = contacts[0];
    EXPECT_EQ(c.key, (ContactKey{ball, box, 0}));
    EXPECT_EQ(c.name, "ball-box");
    const double distance = signed_distance_to_box(q.segment<3>(7 * ball), centre, o, 0.5 * size);
    (distance < 0 ? inside : outside) += 1;
    EXPECT_NEAR(c.gap, distance - r, 1e-13);
    // The box witness lies on the box surface.
    EXPECT_NEAR(signed_distance_to_box(c.point - c.gap * c.normal, centre, o, 0.5 * size), 0.0,
                1e-13);
    EXPECT_EQ(check_contacts(system, q, random_velocities(2, rng), rng), 1);
  }
  EXPECT_EQ(inside, 50);
  EXPECT_EQ(outside, 50);
}

// Keys and gaps of all sphere pairs and sphere–plane pairs within the margin, by testing every
// pair: the oracle for the broad phase.
std::vector<std::pair<ContactKey, double>> brute_force_contacts(const SpatialSystemSpec& spec,
                                                                const Eigen::VectorXd& q,
                                                                double margin) {
  std::vector<std::pair<ContactKey, double>> found;
  const int n = static_cast<int>(spec.bodies.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double gap = (q.segment<3>(7 * i) - q.segment<3>(7 * j)).norm() -
                         spec.bodies[i].radius - spec.bodies[j].radius;
      if (gap < margin) found.push_back({{i, j, 0}, gap});
    }
  for (int i = 0; i < n; ++i)
    for (int p = 0; p < static_cast<int>(spec.planes.size()); ++p) {
      const double gap = spec.planes[p].normal.dot(q.segment<3>(7 * i) - spec.planes[p].point) -
                         spec.bodies[i].radius;
      if (gap < margin) found.push_back({{i, -1, p}, gap});
    }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  return found;
}

void expect_pile_contacts_equal_brute_force(const SpatialSystemSpec& spec, const Eigen::VectorXd& q,
                                            double margin) {
  const System system(spec);
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, Eigen::VectorXd::Zero(system.num_velocities()), margin, contacts);
  std::vector<std::pair<ContactKey, double>> found;
  for (const Contact<double>& c : contacts) found.push_back({c.key, c.gap});
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  const auto expected = brute_force_contacts(spec, q, margin);
  ASSERT_GT(expected.size(), 1000u);  // a real pile: more contacts than spheres
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < found.size(); ++k) {
    ASSERT_EQ(found[k].first, expected[k].first);
    EXPECT_NEAR(found[k].second, expected[k].second, 1e-14);
  }
}

TEST_F(SpatialContacts, PileOfThousandSpheresEqualsBruteForce) {
  const SpatialSystemSpec spec = make_sphere_pile(1000, 21);
  const System system(spec);
  expect_pile_contacts_equal_brute_force(spec, system.initial_positions(), 0.01);
  // A shaken pile: overlaps, larger margin, bodies crossing cells.
  std::mt19937 rng(22);
  Eigen::VectorXd q = system.initial_positions();
  for (int i = 0; i < system.num_bodies(); ++i) q.segment<3>(7 * i) += random_vector(rng, 0.02);
  expect_pile_contacts_equal_brute_force(spec, q, 0.03);
}

TEST_F(SpatialContacts, PileSceneHasNoOverlapsAndStaysInsideItsWalls) {
  const SpatialSystemSpec spec = make_sphere_pile(1000, 5);
  const System system(spec);
  for (const auto& [key, gap] : brute_force_contacts(spec, system.initial_positions(), 0.0))
    ADD_FAILURE() << "overlap " << key.body_a << "/" << key.body_b << " gap " << gap;
  EXPECT_EQ(spec.bodies.size(), 1000u);
  EXPECT_EQ(spec.planes.size(), 5u);
}

TEST_F(SpatialContacts, CuboidPairsAreRefusedRatherThanMissed) {
  SpatialSystemSpec spec;
  spec.bodies = {cuboid("a", Eigen::Vector3d::Constant(1.0)),
                 cuboid("b", Eigen::Vector3d::Constant(1.0))};
  spec.bodies[1].position.x() = 0.9;
  const System system(spec);
  std::vector<Contact<double>> contacts;
  EXPECT_THROW(
      system.find_contacts(system.initial_positions(), system.initial_velocities(), 0.01, contacts),
      std::runtime_error);
  spec.bodies[1].position.x() = 3.0;  // far apart: fine
  const System apart(spec);
  apart.find_contacts(apart.initial_positions(), apart.initial_velocities(), 0.01, contacts);
  EXPECT_TRUE(contacts.empty());
}

TEST_F(SpatialContacts, MarginSelectsCornersAndRejectsBadMargin) {
  SpatialSystemSpec spec;
  spec.bodies = {cuboid("box", Eigen::Vector3d(1.0, 1.0, 1.0))};
  spec.bodies[0].position.z() = 0.505;  // bottom face 5 mm above the floor
  spec.planes = {plane(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ())};
  const System system(spec);
  std::vector<Contact<double>> contacts;
  const Eigen::VectorXd q = system.initial_positions(), v = system.initial_velocities();
  system.find_contacts(q, v, 0.01, contacts);
  ASSERT_EQ(contacts.size(), 4u);
  for (const auto& c : contacts) {
    EXPECT_NEAR(c.gap, 0.005, 1e-15);
    EXPECT_EQ(c.key.feature & 4, 0);  // bottom corners have bit 2 clear
  }
  system.find_contacts(q, v, 0.004, contacts);
  EXPECT_TRUE(contacts.empty());
  EXPECT_THROW(system.find_contacts(q, v, -1.0, contacts), std::invalid_argument);
  EXPECT_THROW(system.find_contacts(q.head(6), v, 0.01, contacts), std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model::spatial
