// Contact names. find_contacts names every contact "<a>-<b>", with "#<feature>" where a polygon
// or a cuboid's corner is involved (the names of the events CSV); find_reachable_contacts, the
// time stepper's search, leaves them empty, also in slots that held a name, and
// write_contact_name gives the same name for a contact's key. The expected names are spelled out
// from the scene's body and plane names, not taken from the code that forms them.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lib/model/planar/narrow_phase.hpp"
#include "lib/model/planar/planar_system.hpp"
#include "lib/model/spatial/spatial_system.hpp"

namespace impactbench::model {
namespace {

constexpr double kAllContacts = 1e3;  // [m] a margin that returns every candidate of the scene

BodySpec body(const std::string& name, ShapeKind shape, const Eigen::Vector3d& position) {
  BodySpec b;
  b.name = name;
  b.shape = shape;
  b.radius = 0.1;
  b.size = shape == ShapeKind::kDisk ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.4, 0.2, 0.3);
  b.position = position;
  return b;
}

// Two disks and a box between a floor and a wall.
struct PlanarNames : ::testing::Test {
  std::vector<BodySpec> bodies{body("ball0", ShapeKind::kDisk, {0.0, 0.1, 0.0}),
                               body("ball1", ShapeKind::kDisk, {0.25, 0.1, 0.0}),
                               body("block", ShapeKind::kBox, {0.6, 0.1, 0.0})};
  std::vector<StaticPlaneSpec> lines{StaticPlaneSpec{"floor", {0, 0, 0}, {0, 1, 0}},
                                     StaticPlaneSpec{"wall", {-0.5, 0, 0}, {1, 0, 0}}};
  planar::PlanarRigidBodySystemd system{bodies, lines, 9.81, {0.5, 0.0}};
  Eigen::VectorXd q = system.initial_positions();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(system.num_velocities());

  // The name by the convention: a line's features are numbered kFeaturesPerPlane apart.
  std::string expected(const ContactKey& key) const {
    const BodySpec& a = bodies[static_cast<std::size_t>(key.body_a)];
    const bool on_line = key.body_b < 0;
    const int line = key.feature / planar::kFeaturesPerPlane;
    const bool polygon =
        a.shape != ShapeKind::kDisk ||
        (!on_line && bodies[static_cast<std::size_t>(key.body_b)].shape != ShapeKind::kDisk);
    const std::string b = on_line ? lines[static_cast<std::size_t>(line)].name
                                  : bodies[static_cast<std::size_t>(key.body_b)].name;
    const int feature = on_line ? key.feature % planar::kFeaturesPerPlane : key.feature;
    return a.name + "-" + b + (polygon ? "#" + std::to_string(feature) : "");
  }
};

TEST_F(PlanarNames, TheSearchNamesEveryContactAndTheKeyGivesTheSameName) {
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, kAllContacts, contacts);
  int disk_pairs = 0, disk_lines = 0, polygon_lines = 0, disk_polygons = 0;
  for (const Contact<double>& c : contacts) {
    EXPECT_EQ(c.name, expected(c.key));
    std::string by_key = "a name to be replaced";
    system.write_contact_name(c.key, by_key);
    EXPECT_EQ(by_key, c.name);
    const bool a_disk = c.key.body_a < 2;
    if (c.key.body_b < 0)
      ++(a_disk ? disk_lines : polygon_lines);
    else
      ++(a_disk && c.key.body_b < 2 ? disk_pairs : disk_polygons);
  }
  // Every kind of name: plain pairs, and "#<feature>" on the block's corners and clip points.
  EXPECT_EQ(disk_pairs, 1);
  EXPECT_EQ(disk_lines, 4);
  EXPECT_GE(polygon_lines, 8);  // four corners on each line
  EXPECT_GE(disk_polygons, 2);
  // Some of them as the events CSV shows them.
  for (const char* name :
       {"ball0-ball1", "ball0-floor", "ball1-wall", "block-floor#0", "block-wall#3"})
    EXPECT_TRUE(std::any_of(contacts.begin(), contacts.end(), [&](const Contact<double>& c) {
      return c.name == name;
    })) << name;
}

TEST_F(PlanarNames, TheReachableSearchLeavesNamesEmptyEvenInSlotsThatHeldOne) {
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, kAllContacts, contacts);
  ASSERT_GT(contacts.size(), 10u);
  ASSERT_FALSE(contacts.front().name.empty());
  const Eigen::VectorXd speed_bound = Eigen::VectorXd::Ones(system.num_velocities());
  ASSERT_TRUE(system.find_reachable_contacts(q, v, speed_bound, 0.01, kAllContacts, contacts));
  ASSERT_GT(contacts.size(), 10u);
  for (const Contact<double>& c : contacts) {
    EXPECT_TRUE(c.name.empty()) << c.name;
    std::string by_key;
    system.write_contact_name(c.key, by_key);
    EXPECT_EQ(by_key, expected(c.key));
  }
}

TEST_F(PlanarNames, AnUnknownKeyIsRefused) {
  std::string name;
  for (const ContactKey& key :
       {ContactKey{-1, -1, 0}, ContactKey{3, -1, 0}, ContactKey{0, 3, 0},
        ContactKey{0, -1, 2 * planar::kFeaturesPerPlane}, ContactKey{0, -1, -1}})
    EXPECT_THROW(system.write_contact_name(key, name), std::invalid_argument)
        << key.body_a << " " << key.body_b << " " << key.feature;
}

// A cuboid and two spheres on a floor, beside a wall.
struct SpatialNames : ::testing::Test {
  static spatial::SpatialSystemSpec scene() {
    spatial::SpatialSystemSpec spec;
    spec.bodies = {body("box", ShapeKind::kCuboid, {0.0, 0.1, 0.0}),
                   body("ball", ShapeKind::kSphere, {0.5, 0.1, 0.0}),
                   body("ball2", ShapeKind::kSphere, {0.8, 0.1, 0.0})};
    spec.planes = {StaticPlaneSpec{"floor", {0, 0, 0}, {0, 1, 0}},
                   StaticPlaneSpec{"wall", {-1, 0, 0}, {1, 0, 0}}};
    return spec;
  }
  spatial::SpatialRigidBodySystem<double> system{scene()};
  Eigen::VectorXd q = system.initial_positions();
  Eigen::VectorXd v = Eigen::VectorXd::Zero(system.num_velocities());
};

TEST_F(SpatialNames, TheSearchNamesEveryContactAndTheKeyGivesTheSameName) {
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, kAllContacts, contacts);
  // Every candidate at this margin: the three pairs (the sphere first), each sphere on each
  // plane (feature = the plane), each of the cuboid's corners on each plane (feature = 8 ×
  // plane + corner).
  std::vector<std::pair<ContactKey, std::string>> expected = {
      {{1, 0, 0}, "ball-box"},    {{2, 0, 0}, "ball2-box"},  {{1, 2, 0}, "ball-ball2"},
      {{1, -1, 0}, "ball-floor"}, {{1, -1, 1}, "ball-wall"}, {{2, -1, 0}, "ball2-floor"},
      {{2, -1, 1}, "ball2-wall"}};
  for (int p = 0; p < 2; ++p)
    for (int corner = 0; corner < 8; ++corner)
      expected.push_back(
          {{0, -1, 8 * p + corner},
           std::string("box-") + (p == 0 ? "floor" : "wall") + "#" + std::to_string(corner)});
  ASSERT_EQ(contacts.size(), expected.size());
  for (const auto& [key, name] : expected) {
    const auto found = std::find_if(contacts.begin(), contacts.end(),
                                    [&](const Contact<double>& c) { return c.key == key; });
    ASSERT_NE(found, contacts.end()) << name;
    EXPECT_EQ(found->name, name);
    std::string by_key = "a name to be replaced";
    system.write_contact_name(key, by_key);
    EXPECT_EQ(by_key, name);
  }
}

TEST_F(SpatialNames, TheReachableSearchLeavesNamesEmptyEvenInSlotsThatHeldOne) {
  std::vector<Contact<double>> contacts;
  system.find_contacts(q, v, kAllContacts, contacts);
  ASSERT_EQ(contacts.size(), 23u);
  const Eigen::VectorXd speed_bound = Eigen::VectorXd::Ones(system.num_velocities());
  ASSERT_TRUE(system.find_reachable_contacts(q, v, speed_bound, 0.01, kAllContacts, contacts));
  ASSERT_EQ(contacts.size(), 23u);
  for (const Contact<double>& c : contacts) EXPECT_TRUE(c.name.empty()) << c.name;
}

TEST_F(SpatialNames, AnUnknownKeyIsRefused) {
  std::string name;
  for (const ContactKey& key :
       {ContactKey{-1, -1, 0}, ContactKey{3, -1, 0}, ContactKey{1, 3, 0}, ContactKey{1, 2, 1},
        ContactKey{1, -1, 2}, ContactKey{0, -1, 16}, ContactKey{0, -1, -1}})
    EXPECT_THROW(system.write_contact_name(key, name), std::invalid_argument)
        << key.body_a << " " << key.body_b << " " << key.feature;
}

}  // namespace
}  // namespace impactbench::model
