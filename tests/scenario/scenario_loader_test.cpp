// Every shipped scenario loads, has the contracted names and a geometry consistent with its
// description (bodies resting where they should, no initial overlaps), and --set overrides
// change exactly what they should.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::scenario {
namespace {

const std::vector<std::string> kShipped = {"bouncing_ball", "box_pyramid",   "cube_toss",
                                           "disk_pile",     "incline",       "newtons_cradle",
                                           "plank_box",     "rocking_block", "sliding_block",
                                           "sphere_pile",   "sphere_spin"};

TEST(ScenarioLoader, ListsExactlyTheShippedScenarios) {
  EXPECT_EQ(list_scenarios(), kShipped);
}

TEST(ScenarioLoader, EveryShippedScenarioLoadsWithConsistentData) {
  for (const auto& name : kShipped) {
    SCOPED_TRACE(name);
    const Scenario s = load_scenario_by_name(name);
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.description.empty());
    EXPECT_GT(s.duration, 0.0);
    EXPECT_GT(s.dt, 0.0);
    EXPECT_LE(s.dt, s.duration);
    EXPECT_GT(s.tolerance, 0.0);
    EXPECT_FALSE(s.engines.empty());
    ASSERT_NE(s.find_parameter("g"), nullptr);
    const double g = s.parameter("g");
    const Eigen::Vector3d expected_gravity =
        s.dimension == Dimension::kPlanar ? Eigen::Vector3d(0, -g, 0) : Eigen::Vector3d(0, 0, -g);
    EXPECT_EQ(s.gravity, expected_gravity);
    EXPECT_FALSE(s.bodies.empty());
    for (const auto& p : s.parameters) EXPECT_EQ(p.value, p.default_value) << p.name;
    for (const auto& q : s.analytic_quantities)
      EXPECT_TRUE(std::isfinite(s.analytic(q.name, 0))) << q.name;
    // Box2D cannot run spatial scenes (Bullet runs planar ones held in the plane).
    EXPECT_NE(s.supports_engine("box2d") && s.dimension == Dimension::kSpatial, true);
  }
}

/// Distance from a body's lowest point (disk/sphere or, for an axis-aligned or rotated box,
/// its lowest corner) to a plane, along the plane's normal.
double clearance(const model::BodySpec& body, const model::StaticPlaneSpec& plane) {
  const double centre = (body.position - plane.point).dot(plane.normal);
  if (body.shape == model::ShapeKind::kDisk || body.shape == model::ShapeKind::kSphere)
    return centre - body.radius;
  double lowest = centre;
  for (const double sx : {-0.5, 0.5})
    for (const double sy : {-0.5, 0.5}) {
      const Eigen::Vector3d corner =
          body.orientation * Eigen::Vector3d(sx * body.size.x(), sy * body.size.y(), 0.0);
      lowest = std::min(lowest, centre + corner.dot(plane.normal));
    }
  return lowest;
}

TEST(ScenarioLoader, BouncingBallStartsAtRestAtTheGivenHeight) {
  const Scenario s = load_scenario_by_name("bouncing_ball");
  ASSERT_EQ(s.bodies.size(), 1u);
  const auto& ball = s.bodies[0];
  EXPECT_EQ(ball.name, "ball");
  EXPECT_EQ(ball.shape, model::ShapeKind::kDisk);
  EXPECT_EQ(ball.radius, 0.1);
  EXPECT_EQ(ball.mass, 1.0);
  EXPECT_EQ(ball.position, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(ball.velocity, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.material.restitution, 0.9);
  EXPECT_EQ(s.material.friction, 0.0);
  ASSERT_EQ(s.planes.size(), 1u);
  EXPECT_EQ(s.planes[0].normal, Eigen::Vector3d::UnitY());
  EXPECT_GT(s.duration, s.analytic("t_inf"));  // the run must pass the accumulation point
}

TEST(ScenarioLoader, BlocksRestOnTheirSupport) {
  for (const auto* name : {"sliding_block", "incline", "box_pyramid"}) {
    SCOPED_TRACE(name);
    const Scenario s = load_scenario_by_name(name);
    double lowest = INFINITY;  // the bottom row (pyramid) touches, nothing penetrates
    for (const auto& body : s.bodies) lowest = std::min(lowest, clearance(body, s.planes.front()));
    EXPECT_NEAR(lowest, 0.0, 1e-12);
  }
  const Scenario incline = load_scenario_by_name("incline");
  const double alpha = 20.0 * M_PI / 180.0;
  EXPECT_NEAR(incline.planes[0].normal.x(), -std::sin(alpha), 1e-15);
  EXPECT_NEAR(incline.planes[0].normal.y(), std::cos(alpha), 1e-15);
  EXPECT_NEAR(incline.bodies[0].angle, alpha, 1e-15);
  // The push points down the slope, perpendicular to the normal.
  ASSERT_EQ(incline.inputs.size(), 1u);
  EXPECT_EQ(incline.inputs[0].body, "block");
  EXPECT_NEAR(incline.inputs[0].direction.dot(incline.planes[0].normal), 0.0, 1e-15);
  EXPECT_LT(incline.inputs[0].direction.y(), 0.0);
}

TEST(ScenarioLoader, RockingBlockRestsOnItsLeftCornerOnly) {
  const Scenario s = load_scenario_by_name("rocking_block");
  const auto& block = s.bodies[0];
  const Eigen::Vector3d left = block.position + block.orientation * Eigen::Vector3d(-0.1, -0.5, 0);
  const Eigen::Vector3d right = block.position + block.orientation * Eigen::Vector3d(0.1, -0.5, 0);
  EXPECT_NEAR(left.x(), -0.1, 1e-15);
  EXPECT_NEAR(left.y(), 0.0, 1e-15);
  EXPECT_NEAR(right.y(), 0.2 * std::sin(5.0 * M_PI / 180.0), 1e-15);
}

TEST(ScenarioLoader, NewtonsCradleSpacesTheBallsByTheGap) {
  const Scenario s = load_scenario_by_name("newtons_cradle", {{"count", 5}});
  ASSERT_EQ(s.bodies.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(s.bodies[static_cast<std::size_t>(i)].name, "ball" + std::to_string(i));
    EXPECT_NEAR(s.bodies[static_cast<std::size_t>(i)].position.x(), i * 0.21, 1e-15);
    EXPECT_EQ(s.bodies[static_cast<std::size_t>(i)].velocity.x(), i == 0 ? 1.0 : 0.0);
  }
  EXPECT_EQ(s.gravity, Eigen::Vector3d::Zero());
  EXPECT_TRUE(s.planes.empty());
}

/// Pairwise disjoint and inside the walls (every plane of the scenario).
void expect_separated_and_inside(const Scenario& s) {
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    for (const auto& plane : s.planes)
      EXPECT_GT(clearance(s.bodies[a], plane), 0.0) << s.bodies[a].name;
    for (std::size_t b = a + 1; b < s.bodies.size(); ++b)
      EXPECT_GT((s.bodies[a].position - s.bodies[b].position).norm(),
                s.bodies[a].radius + s.bodies[b].radius)
          << s.bodies[a].name << " " << s.bodies[b].name;
  }
}

TEST(ScenarioLoader, PilesStartSeparatedInsideTheBoxAndAreReproducible) {
  const Scenario disks = load_scenario_by_name("disk_pile");
  EXPECT_EQ(disks.bodies.size(), 100u);
  EXPECT_EQ(disks.planes.size(), 3u);
  expect_separated_and_inside(disks);
  const Scenario spheres = load_scenario_by_name("sphere_pile", {{"count", 200}});
  EXPECT_EQ(spheres.bodies.size(), 200u);
  EXPECT_EQ(spheres.planes.size(), 5u);
  expect_separated_and_inside(spheres);
  // Same file, same parameters: the same placement; another seed: a different one.
  EXPECT_EQ(load_scenario_by_name("disk_pile").bodies[17].position, disks.bodies[17].position);
  EXPECT_NE(load_scenario_by_name("disk_pile", {{"seed", 1}}).bodies[17].position,
            disks.bodies[17].position);
}

TEST(ScenarioLoader, PyramidRowsRestOnTheRowBelow) {
  const Scenario s = load_scenario_by_name("box_pyramid", {{"rows", 4}});
  ASSERT_EQ(s.bodies.size(), 10u);
  // Top row first: box0; bottom row: box6 .. box9 on the ground at x = -1.5, -0.5, 0.5, 1.5 pitch.
  const double pitch = 0.21;
  EXPECT_NEAR(s.bodies[0].position.y(), 0.1 + 3 * 0.2, 1e-15);
  EXPECT_NEAR(s.bodies[0].position.x(), 0.0, 1e-15);
  for (int c = 0; c < 4; ++c) {
    const auto& box = s.bodies[static_cast<std::size_t>(6 + c)];
    EXPECT_NEAR(box.position.x(), (c - 1.5) * pitch, 1e-15);
    EXPECT_NEAR(box.position.y(), 0.1, 1e-15);
  }
  EXPECT_DOUBLE_EQ(s.analytic("top_height"), s.bodies[0].position.y());
  EXPECT_EQ(s.analytic("box_count"), 10.0);
}

TEST(ScenarioLoader, SphereSpinAndPlankBoxCarryTheirStates) {
  const Scenario spin = load_scenario_by_name("sphere_spin");
  EXPECT_EQ(spin.dimension, Dimension::kSpatial);
  EXPECT_EQ(spin.bodies[0].shape, model::ShapeKind::kSphere);
  EXPECT_EQ(spin.bodies[0].position, Eigen::Vector3d(0, 0, 0.1));
  EXPECT_EQ(spin.bodies[0].angular_velocity, Eigen::Vector3d(0, -10, 5));
  const Scenario plank = load_scenario_by_name("plank_box", {{"tilt", 10}});
  EXPECT_EQ(plank.system, SystemKind::kPlankBox);
  ASSERT_NE(plank.find_body("box"), nullptr);
  ASSERT_NE(plank.find_body("plank"), nullptr);
  // The lowest corner starts `height` above the plank's top surface l_P/2.
  model::StaticPlaneSpec top;
  top.point = Eigen::Vector3d(0, plank.parameter("l_P") / 2, 0);
  EXPECT_NEAR(clearance(*plank.find_body("box"), top), 0.1, 1e-15);
  for (const auto* name : {"m_B", "L_B", "l_B", "m_P", "L_P", "l_P", "k_P", "b_P", "friction",
                           "restitution", "tilt", "vx", "vy", "height"})
    EXPECT_NE(plank.find_parameter(name), nullptr) << name;
}

/// Writes `text` to a fresh <name>.toml in the temporary directory and returns its path.
std::filesystem::path write_scenario(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / (name + ".toml");
  std::ofstream(path) << text;
  return path;
}

const char* const kSpatialHeader = R"(name = "NAME"
description = "spatial features"
dimension = "spatial"
system = "rigid_bodies"
engines = ["moreau", "bullet"]
duration = 1
dt = 0.01
tolerance = 1e-9
[parameters]
g = { default = 9.81, unit = "m/s^2", description = "gravity" }
n = { default = 3, unit = "1", description = "count" }
[material]
friction = 0.2
restitution = 0.3
)";

std::string spatial_scenario(const std::string& name, const std::string& bodies) {
  std::string text = kSpatialHeader;
  text.replace(text.find("NAME"), 4, name);
  return text + bodies;
}

TEST(ScenarioLoader, SpatialCuboidsWithRepeatOrientationAndCubeSize) {
  const auto path =
      write_scenario("impactbench_spatial_ok", spatial_scenario("impactbench_spatial_ok", R"(
[[bodies]]
name = "crate{i}_of_{i}"
repeat = "n"
shape = "cuboid"
size = "0.5 + i"
mass = "1 + i"
position = ["i", "2*i", "i^2"]
orientation = [2, 0, 0, 2]
velocity = [1, 2, 3]
angular_velocity = [0, 0, "i"]
inertia = [1, 1, "1 + i/2"]
)"));
  const Scenario s = load_scenario(path);
  std::filesystem::remove(path);
  ASSERT_EQ(s.bodies.size(), 3u);
  EXPECT_EQ(s.gravity, Eigen::Vector3d(0, 0, -9.81));
  for (int i = 0; i < 3; ++i) {
    const auto& body = s.bodies[static_cast<std::size_t>(i)];
    EXPECT_EQ(body.name, "crate" + std::to_string(i) + "_of_" + std::to_string(i));
    EXPECT_EQ(body.shape, model::ShapeKind::kCuboid);
    EXPECT_EQ(body.size, Eigen::Vector3d::Constant(0.5 + i));
    EXPECT_EQ(body.mass, 1.0 + i);
    EXPECT_EQ(body.position, Eigen::Vector3d(i, 2 * i, i * i));
    // [2, 0, 0, 2] normalised: a quarter turn about z.
    EXPECT_NEAR(body.orientation.w(), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(body.orientation.z(), std::sqrt(0.5), 1e-15);
    EXPECT_EQ(body.velocity, Eigen::Vector3d(1, 2, 3));
    EXPECT_EQ(body.angular_velocity, Eigen::Vector3d(0, 0, i));
    ASSERT_TRUE(body.inertia.has_value());
    EXPECT_EQ(*body.inertia, Eigen::Vector3d(1, 1, 1 + i / 2.0));  // i = 2: 2 = 1 + 1, allowed
  }
}

TEST(ScenarioLoader, SpatialFieldErrorsNameTheField) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"shape = \"disk\"\nradius = 1", "bodies[0].shape: 'disk' is not a spatial shape"},
      {"shape = \"sphere\"\nradius = 1\nangle = 0.5", "bodies[0].angle: only for planar scenarios"},
      {"shape = \"sphere\"\nradius = 1\norientation = [0, 0, 0, 0]",
       "bodies[0].orientation: a quaternion [w, x, y, z] must not be zero"},
      {"shape = \"cuboid\"\nsize = [1, 1]",
       "bodies[0].size: expected 3 components (spatial), got 2"},
      {"shape = \"sphere\"\nradius = 1\nrepeat = \"n - 0.5\"",
       "bodies[0].repeat: must be a whole number"},
      {"shape = \"cuboid\"\nsize = 1\ninertia = [1, 1, 2.5]",
       "bodies[0].inertia: moment 2.5 exceeds the sum of the other two (2)"},
      {"shape = \"cuboid\"\nsize = 1\ninertia = [1, 0, 1]",
       "bodies[0].inertia: moments must be finite and > 0 (got 0)"},
      {"shape = \"cuboid\"\nsize = 1\ninertia = [1, 1]",
       "bodies[0].inertia: expected 3 components (spatial), got 2"},
  };
  for (const auto& [fields, message] : cases) {
    const std::string name = "impactbench_spatial_bad";
    const auto path = write_scenario(
        name,
        spatial_scenario(
            name, "[[bodies]]\nname = \"b{i}\"\nmass = 1\nposition = [0, 0, 1]\n" + fields + "\n"));
    try {
      load_scenario(path);
      ADD_FAILURE() << "accepted: " << fields;
    } catch (const ScenarioError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
      EXPECT_GT(error.line(), 16);
    }
    std::filesystem::remove(path);
  }
}

TEST(ScenarioOverrides, ChangeParametersAndEverythingDerivedFromThem) {
  const Scenario s =
      load_scenario_by_name("bouncing_ball", {{"height", 2.0}, {"restitution", 0.5}});
  EXPECT_EQ(s.parameter("height"), 2.0);
  EXPECT_EQ(s.find_parameter("height")->default_value, 1.0);
  EXPECT_EQ(s.bodies[0].position.y(), 2.0);
  EXPECT_EQ(s.material.restitution, 0.5);
  EXPECT_DOUBLE_EQ(s.analytic("apex", 0), 2.0);
}

TEST(ScenarioOverrides, UnknownNameIsRejectedWithTheValidNames) {
  try {
    load_scenario_by_name("sliding_block", {{"speed", 3.0}});
    FAIL() << "no error";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.field(), "--set speed");
    EXPECT_EQ(error.line(), 0);
    EXPECT_NE(error.problem().find("valid: g, size, mass, friction, restitution, v0"),
              std::string::npos)
        << error.what();
  }
}

TEST(ScenarioOverrides, InvalidValuesAreReportedAtTheFieldThatUsesThem) {
  try {
    load_scenario_by_name("sliding_block", {{"friction", -0.5}});
    FAIL() << "no error";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.field(), "material.friction");
    EXPECT_GT(error.line(), 0);
  }
  EXPECT_THROW(load_scenario_by_name("bouncing_ball", {{"mass", 0.0}}), ScenarioError);
  EXPECT_THROW(load_scenario_by_name("bouncing_ball", {{"restitution", 1.01}}), ScenarioError);
}

TEST(ScenarioOverrides, ParseOverrideAcceptsOnlyNameEqualsNumber) {
  EXPECT_EQ(parse_override("height=2.5"), std::make_pair(std::string("height"), 2.5));
  EXPECT_EQ(parse_override("g=-1e-3"), std::make_pair(std::string("g"), -1e-3));
  for (const auto* bad : {"height", "=2", "height=", "height=2x", "height=nan", "height=inf"})
    EXPECT_THROW(parse_override(bad), std::invalid_argument) << bad;
}

TEST(ScenarioCatalog, EnvironmentVariableSelectsAnotherDirectory) {
  ::setenv("IMPACTBENCH_SCENARIOS", IMPACTBENCH_TEST_DATA_DIR "/scenarios_bad", 1);
  const auto names = list_scenarios();
  ::unsetenv("IMPACTBENCH_SCENARIOS");
  EXPECT_GE(names.size(), 10u);
  EXPECT_NE(std::find(names.begin(), names.end(), "missing_mass"), names.end());
  EXPECT_THROW(load_scenario_by_name("no_such_scenario"), ScenarioError);
}

}  // namespace
}  // namespace impactbench::scenario
