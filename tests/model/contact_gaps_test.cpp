// find_contact_gaps, what the event-driven integrator's guards read between events: the key and
// gap of every contact find_contacts finds, in the same order and to the bit. The planar system
// forms the gaps alone (feature_normal, as evaluate_contact); other systems take them from
// find_contacts. Scenes of disks and of rotated boxes at perturbed, moving states cover each
// kind of contact normal; bad states are refused as find_contacts refuses them.
#include <array>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "lib/model/planar/planar_scenes.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/spatial/spatial_scenes.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::model {
namespace {

constexpr double kMargin = 0.02;  // [m]: wide, so that near and touching pairs are both found

Eigen::VectorXd perturbed(const Eigen::VectorXd& x, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-size, size);
  Eigen::VectorXd out = x;
  for (Eigen::Index i = 0; i < out.size(); ++i) out[i] += offset(rng);
  return out;
}

// The gaps equal the contacts' keys and gaps entry by entry, bit for bit.
template <typename System>
void expect_gaps_of_contacts(const System& system, const Eigen::VectorXd& q,
                             const Eigen::VectorXd& v, std::size_t at_least) {
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, kMargin, contacts);
  std::vector<ContactGap> gaps = {{{7, 8, 9}, 1.0}};  // stale content, replaced
  system.find_contact_gaps(q, v, kMargin, gaps);
  ASSERT_GE(contacts.size(), at_least);
  ASSERT_EQ(gaps.size(), contacts.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    EXPECT_EQ(gaps[i].key, contacts[i].key) << contacts[i].name;
    EXPECT_EQ(gaps[i].gap, contacts[i].gap) << contacts[i].name;
  }
}

// How many of the planar system's features at q have each kind of normal.
std::array<int, 3> normal_kinds(const planar::PlanarRigidBodySystemd& system,
                                const Eigen::VectorXd& q) {
  std::array<int, 3> count{};
  for (const planar::ContactFeature& f : system.detect_features(q, kMargin))
    ++count[static_cast<std::size_t>(f.kind)];
  return count;
}

TEST(ContactGaps, PlanarDisksGiveTheirContactsGapsBitForBit) {
  const auto scene = planar::make_disk_pile(200, 4);
  const planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = perturbed(system.initial_positions(), 0.01, 1);
  const Eigen::VectorXd v = perturbed(Eigen::VectorXd::Zero(q.size()), 2.0, 2);
  expect_gaps_of_contacts(system, q, v, 50);
  const auto kinds = normal_kinds(system, q);
  EXPECT_GT(kinds[static_cast<std::size_t>(planar::NormalKind::kFixedNormal)], 0);
  EXPECT_GT(kinds[static_cast<std::size_t>(planar::NormalKind::kAlongSeparation)], 0);
}

TEST(ContactGaps, PlanarRotatedBoxesGiveTheirContactsGapsBitForBit) {
  const auto scene = planar::make_box_pyramid(8);
  const planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  // Tilted by up to 0.02 rad and shifted by up to 5 mm: corners of one box near the faces of
  // the next.
  const Eigen::VectorXd q = perturbed(system.initial_positions(), 0.005, 3);
  const Eigen::VectorXd v = perturbed(Eigen::VectorXd::Zero(q.size()), 1.0, 4);
  expect_gaps_of_contacts(system, q, v, 20);
  const auto kinds = normal_kinds(system, q);
  EXPECT_GT(kinds[static_cast<std::size_t>(planar::NormalKind::kFixedNormal)], 0);
  EXPECT_GT(kinds[static_cast<std::size_t>(planar::NormalKind::kNormalOfB)], 0);
}

TEST(ContactGaps, SpatialSpheresGiveTheirContactsGaps) {
  const spatial::SpatialRigidBodySystem<double> system(spatial::make_sphere_pile(100, 5));
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = perturbed(Eigen::VectorXd::Zero(system.num_velocities()), 1.0, 6);
  expect_gaps_of_contacts(system, q, v, 20);
}

TEST(ContactGaps, RefusesTheStatesFindContactsRefuses) {
  const auto scene = planar::make_disk_pile(10, 1);
  const planar::PlanarRigidBodySystemd system(scene.bodies, scene.planes, 9.81, {0.5, 0.0});
  const Eigen::VectorXd q = system.initial_positions();
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(q.size());
  std::vector<ContactGap> gaps;
  EXPECT_THROW(system.find_contact_gaps(q.head(3), v, kMargin, gaps), std::invalid_argument);
  EXPECT_THROW(system.find_contact_gaps(q, v.head(3), kMargin, gaps), std::invalid_argument);
  Eigen::VectorXd not_finite = q;
  not_finite[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(system.find_contact_gaps(not_finite, v, kMargin, gaps), std::invalid_argument);
  EXPECT_THROW(system.find_contact_gaps(q, v, -1.0, gaps), std::invalid_argument);
  EXPECT_THROW(system.find_contact_gaps(q, v, std::numeric_limits<double>::quiet_NaN(), gaps),
               std::invalid_argument);

  const spatial::SpatialRigidBodySystem<double> spheres(spatial::make_sphere_pile(10, 1));
  const Eigen::VectorXd qs = spheres.initial_positions();
  EXPECT_THROW(spheres.find_contact_gaps(
                   qs.head(5), Eigen::VectorXd::Zero(spheres.num_velocities()), kMargin, gaps),
               std::invalid_argument);
}

}  // namespace
}  // namespace impactbench::model
