// find_reachable_contacts, the one-search candidate set of the time stepper: every contact
// within the margin after the bodies move for h at their velocities (the predicted state) must
// be among the contacts it returns at the start, and every contact it returns must satisfy its
// definition: gap at q below the margin plus the reach h (|v_centre| + |ω| r) of both bodies.
// Planar disks and rotating boxes, spatial spheres; moving fast enough (up to 3 m/s and 30 rad/s
// over 10 ms) that the reach is several times the margin.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::model {
namespace {

constexpr double kMargin = 0.005;  // [m]
constexpr double kHorizon = 0.01;  // [s]

// A contact's pair of bodies, or its body and feature against a plane (a polygon's vertex). The
// feature of a body–body contact (a clipping point) is chosen by the configuration and may
// differ between q and the predicted state, and so may which body is named first; the pair may
// not.
ContactKey pair_of(const ContactKey& key) {
  if (key.body_b < 0) return key;
  return {std::min(key.body_a, key.body_b), std::max(key.body_a, key.body_b), 0};
}

std::set<ContactKey> pairs(const std::vector<Contact<double>>& contacts) {
  std::set<ContactKey> out;
  for (const auto& c : contacts) out.insert(pair_of(c.key));
  return out;
}

Eigen::VectorXd random_velocities(int bodies, int per_body, int linear, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> speed(-3.0, 3.0), spin(-30.0, 30.0);
  Eigen::VectorXd v(bodies * per_body);
  for (int i = 0; i < bodies; ++i)
    for (int k = 0; k < per_body; ++k) v(i * per_body + k) = k < linear ? speed(rng) : spin(rng);
  return v;
}

// The predicted contacts are among the reachable ones, and each reachable contact's gap is
// below the margin plus the reaches of its bodies.
template <typename System>
void check_reachable(const System& system, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     const std::vector<double>& reach) {
  std::vector<Contact<double>> predicted, reachable;
  system.find_contacts(system.integrate_position(q, v, kHorizon), v, kMargin, predicted);
  ASSERT_TRUE(system.find_reachable_contacts(q, v, v.cwiseAbs(), kHorizon, kMargin, reachable));
  ASSERT_GT(predicted.size(), 50u);  // the scene must actually be in contact
  const auto reachable_pairs = pairs(reachable);
  for (const auto& c : predicted)
    EXPECT_TRUE(reachable_pairs.count(pair_of(c.key)))
        << c.name << " is within the margin at the predicted state but was not found";
  double max_reach = 0.0;
  for (const double r : reach) max_reach = std::max(max_reach, r);
  EXPECT_GT(max_reach, 4.0 * kMargin);  // the reach must matter
  for (const auto& c : reachable) {
    const double bound = kMargin + reach[static_cast<std::size_t>(c.key.body_a)] +
                         (c.key.body_b >= 0 ? reach[static_cast<std::size_t>(c.key.body_b)] : 0.0);
    EXPECT_LT(c.gap, bound) << c.name;
  }
  // More than the contacts within the margin at q: the search looked further.
  std::vector<Contact<double>> near;
  system.find_contacts(q, v, kMargin, near);
  EXPECT_GT(reachable.size(), near.size());
}

TEST(ReachableContacts, DiskPileContainsThePredictedContacts) {
  const auto scene = planar::make_disk_pile(400, 3);
  const planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = random_velocities(system.num_bodies(), 3, 2, 17);
  std::vector<double> reach;
  for (int i = 0; i < system.num_bodies(); ++i)
    reach.push_back(kHorizon *
                    (v.segment<2>(3 * i).norm() + std::abs(v(3 * i + 2)) * system.body(i).radius));
  check_reachable(system, q, v, reach);
}

TEST(ReachableContacts, SpinningBoxesContainThePredictedContacts) {
  const auto scene = planar::make_box_pyramid(12);
  const planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = system.initial_positions();
  // Boxes of 0.5 m spinning at up to 30 rad/s: corners travel up to 0.1 m in 10 ms.
  const Eigen::VectorXd v = random_velocities(system.num_bodies(), 3, 2, 5);
  std::vector<double> reach;
  for (int i = 0; i < system.num_bodies(); ++i) {
    const double half_diagonal = 0.5 * system.body(i).size.head<2>().norm();
    reach.push_back(kHorizon *
                    (v.segment<2>(3 * i).norm() + std::abs(v(3 * i + 2)) * half_diagonal));
  }
  check_reachable(system, q, v, reach);
}

TEST(ReachableContacts, SpherePileContainsThePredictedContacts) {
  const spatial::SpatialRigidBodySystem<double> system(spatial::make_sphere_pile(400, 2));
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = random_velocities(system.num_bodies(), 6, 3, 9);
  std::vector<double> reach;
  for (int i = 0; i < system.num_bodies(); ++i)
    reach.push_back(kHorizon * (v.segment<3>(6 * i).norm() +
                                v.segment<3>(6 * i + 3).norm() * system.spec().bodies[i].radius));
  check_reachable(system, q, v, reach);
}

TEST(ReachableContacts, RejectsABadSpeedBound) {
  const auto scene = planar::make_disk_pile(40, 1);
  const planar::PlanarRigidBodySystemd planar_system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = planar_system.initial_positions();
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(q.size());
  std::vector<Contact<double>> out;
  EXPECT_THROW(
      planar_system.find_reachable_contacts(q, v, Eigen::VectorXd::Zero(3), kHorizon, kMargin, out),
      std::invalid_argument);
  Eigen::VectorXd nan_speed = Eigen::VectorXd::Zero(q.size());
  nan_speed(4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(planar_system.find_reachable_contacts(q, v, nan_speed, kHorizon, kMargin, out),
               std::invalid_argument);
  Eigen::VectorXd negative_speed = Eigen::VectorXd::Zero(q.size());
  negative_speed(7) = -1.0;  // a bound on |v| cannot be negative
  EXPECT_THROW(planar_system.find_reachable_contacts(q, v, negative_speed, kHorizon, kMargin, out),
               std::invalid_argument);

  const spatial::SpatialRigidBodySystem<double> spatial_system(spatial::make_sphere_pile(40, 1));
  const Eigen::VectorXd qs = spatial_system.initial_positions();
  const Eigen::VectorXd vs = Eigen::VectorXd::Zero(spatial_system.num_velocities());
  EXPECT_THROW(spatial_system.find_reachable_contacts(qs, vs, Eigen::VectorXd::Zero(5), kHorizon,
                                                      kMargin, out),
               std::invalid_argument);
  Eigen::VectorXd infinite_speed = Eigen::VectorXd::Zero(vs.size());
  infinite_speed(2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(
      spatial_system.find_reachable_contacts(qs, vs, infinite_speed, kHorizon, kMargin, out),
      std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model
