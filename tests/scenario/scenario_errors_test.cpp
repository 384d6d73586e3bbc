// Each malformed file in tests/data/scenarios_bad/ is rejected with a ScenarioError naming the
// file, the line and the field, and saying what is wrong, as "<path>:<line>: <field>: <what>".
#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::scenario {
namespace {

struct BadFile {
  const char* file;
  int line;
  const char* field;
  const char* problem;  // a part of the message that says what is wrong
};

std::ostream& operator<<(std::ostream& out, const BadFile& bad) {
  return out << bad.file;
}

class ScenarioErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(ScenarioErrors, NamePathLineAndField) {
  const BadFile& bad = GetParam();
  const std::string path = std::string(IMPACTBENCH_TEST_DATA_DIR "/scenarios_bad/") + bad.file;
  try {
    load_scenario(path);
    FAIL() << bad.file << " was accepted";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.path(), path);
    EXPECT_EQ(error.line(), bad.line) << error.what();
    EXPECT_EQ(error.field(), bad.field) << error.what();
    EXPECT_NE(error.problem().find(bad.problem), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()),
              path + ":" + std::to_string(bad.line) + ": " + bad.field + ": " + error.problem());
  }
}

INSTANTIATE_TEST_SUITE_P(
    MalformedFiles, ScenarioErrors,
    ::testing::Values(
        BadFile{"syntax_error.toml", 2, "syntax", ""},
        BadFile{"missing_mass.toml", 18, "bodies[0].mass", "missing required field"},
        BadFile{"negative_mass.toml", 22, "bodies[0].mass", "must be > 0"},
        BadFile{"bad_expression.toml", 23, "bodies[0].position[1]", "unknown name 'heigth'"},
        BadFile{"negative_friction.toml", 15, "material.friction", "must be >= 0"},
        BadFile{"restitution_above_one.toml", 16, "material.restitution",
                "must be in [0, 1] (got 2)"},
        BadFile{"zero_radius.toml", 21, "bodies[0].radius", "must be > 0"},
        BadFile{"unknown_shape.toml", 20, "bodies[0].shape", "unknown shape 'triangle'"},
        BadFile{"unknown_engine.toml", 5, "engines[1]", "unknown engine 'physx'"},
        BadFile{"nan_angle.toml", 23, "bodies[0].angle", "is not finite"},
        BadFile{"wrong_type.toml", 22, "bodies[0].mass", "got boolean"},
        BadFile{"missing_g.toml", 10, "parameters.g", "missing required parameter"},
        BadFile{"circular_derived.toml", 15, "derived.a", "circular definition a -> b -> a"},
        BadFile{"misspelt_field.toml", 16, "material.restitutoin", "unknown field"},
        BadFile{"repeat_without_index.toml", 19, "bodies[0].name", "'{i}'"},
        BadFile{"wrong_vector_size.toml", 28, "planes[0].normal", "expected 2 components"},
        BadFile{"zero_box_side.toml", 21, "bodies[0].size", "side lengths must be > 0"},
        BadFile{"unknown_dimension.toml", 3, "dimension", "'3d' is not one of"},
        BadFile{"text_reference_trajectory.toml", 9, "reference_trajectory", "got string"}),
    [](const auto& test_info) {
      std::string name = test_info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(ScenarioErrors, MissingFileIsNamed) {
  try {
    load_scenario("/nonexistent/dir/ghost.toml");
    FAIL();
  } catch (const ScenarioError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/dir/ghost.toml: no such scenario file");
  }
}

}  // namespace
}  // namespace impactbench::scenario
