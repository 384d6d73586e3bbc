// The scenario loader on hostile or degenerate input: nesting and line lengths that would
// overflow the parser's stack are refused with a line number, a long chain of [derived] names
// is evaluated once per name, a repeat count of zero is refused, and a formula that cannot be
// evaluated for the user's values names the --set parameter behind it — without stopping a
// scenario that does not need it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "lib/scenario/scenario.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::scenario {
namespace {

namespace fs = std::filesystem;

/// A minimal valid scenario whose text can be extended; written as <dir>/<name>.toml.
std::string minimal_scenario(const std::string& name, const std::string& extra_parameters = "",
                             const std::string& tail = "") {
  return "name = \"" + name +
         "\"\n"
         "description = \"hardening test\"\n"
         "dimension = \"planar\"\n"
         "system = \"rigid_bodies\"\n"
         "engines = [\"moreau\"]\n"
         "duration = 1.0\n"
         "dt = 1e-3\n"
         "tolerance = 1e-10\n"
         "[parameters]\n"
         "g = { default = 9.81, unit = \"m/s^2\", description = \"gravity\" }\n" +
         extra_parameters +
         "[material]\n"
         "friction = 0.0\n"
         "restitution = 0.5\n"
         "[[bodies]]\n"
         "name = \"ball\"\n"
         "shape = \"disk\"\n"
         "radius = 0.1\n"
         "mass = 1.0\n"
         "position = [0, 1]\n" +
         tail;
}

class ScenarioHardening : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "impactbench_hardening_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
  }
  void TearDown() override { fs::remove_all(directory_); }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path path = directory_ / (name + ".toml");
    std::ofstream(path) << text;
    return path;
  }

  /// The ScenarioError message of loading `path`, or "" if it loads.
  static std::string error_of(const fs::path& path, const ParameterOverrides& overrides = {},
                              std::optional<double> duration = std::nullopt) {
    try {
      load_scenario(path, overrides, duration);
    } catch (const ScenarioError& error) {
      return error.what();
    }
    return "";
  }

  fs::path directory_;
};

TEST_F(ScenarioHardening, DottedKeyOfAHundredThousandLevelsIsRefusedByLineLength) {
  std::string key = "a";
  for (int level = 1; level < 100000; ++level) key += ".a";
  const std::string before = minimal_scenario("deep") + "[analytic]\n";
  const fs::path path = write("deep", before + key + " = 1\n");
  const auto line = std::count(before.begin(), before.end(), '\n') + 1;
  const std::string message = error_of(path);
  EXPECT_NE(message.find(path.string() + ":" + std::to_string(line) +
                         ": syntax: line longer than 4096 characters"),
            std::string::npos)
      << message;
}

TEST_F(ScenarioHardening, TableHeaderNestedBeyondTheLimitIsRefused) {
  // 100 levels fit in a short line; the document tree allows 64.
  std::string header = "[x";
  for (int level = 1; level < 100; ++level) header += ".x";
  const fs::path path = write("nested", minimal_scenario("nested") + header + "]\ny = 1\n");
  const std::string message = error_of(path);
  EXPECT_NE(message.find("nested deeper than 64 levels"), std::string::npos) << message;
}

TEST_F(ScenarioHardening, LongChainOfDerivedNamesIsEvaluatedOncePerName) {
  // f0 = f1 = 1, f(k) = f(k-1) + f(k-2): f44 is the Fibonacci number F(45) = 1134903170.
  // Evaluating every dependency on every path would take about 2^44 evaluations.
  std::string derived = "[derived]\nf0 = 1\nf1 = 1\n";
  for (int k = 2; k <= 44; ++k) {
    // Appends only: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string at -O3.
    for (const std::string& piece :
         {std::string("f"), std::to_string(k), std::string(" = \"f"), std::to_string(k - 1),
          std::string(" + f"), std::to_string(k - 2), std::string("\"\n")})
      derived += piece;
  }
  // The body's mass reads the end of the chain: f44 / 1134903170 must be exactly 1.
  std::string text = minimal_scenario("chain", "", derived);
  text.replace(text.find("mass = 1.0"), 10, "mass = \"f44 / 1134903170\"");
  const Scenario s = load_scenario(write("chain", text));
  EXPECT_EQ(s.bodies.at(0).mass, 1.0);
}

TEST_F(ScenarioHardening, RepeatCountZeroLeavesNoBodyAndIsRefused) {
  std::string text =
      minimal_scenario("empty", "count = { default = 3, unit = \"1\", description = \"balls\" }\n");
  text.replace(text.find("name = \"ball\""), 13, "name = \"ball{i}\"\nrepeat = \"count\"");
  const fs::path path = write("empty", text);
  ASSERT_EQ(error_of(path), "");
  const std::string message = error_of(path, {{"count", 0.0}});
  EXPECT_NE(message.find("bodies: no body to simulate"), std::string::npos) << message;
}

TEST_F(ScenarioHardening, NonFiniteDerivedValueStopsOnlyTheFieldsThatReadIt) {
  // bouncing_ball's layout: t_first = sqrt(2 (h - r) / g) is infinite for g = 0, but the
  // duration caps it, so the scenario loads; a body mass that reads it does not.
  const std::string derived = "[derived]\nt_first = \"sqrt(2*(1 - 0.1)/g)\"\n";
  std::string text = minimal_scenario("zero_g");
  text.insert(text.find("[material]"), derived);
  text.replace(text.find("duration = 1.0"), 14, "duration = \"min(3*t_first, 60)\"");
  const fs::path path = write("zero_g", text);
  const Scenario s = load_scenario(path, {{"g", 0.0}});
  EXPECT_EQ(s.duration, 60.0);
  // With g = 9.81: 3 sqrt(1.8 / 9.81).
  EXPECT_DOUBLE_EQ(load_scenario(path).duration, 3 * std::sqrt(1.8 / 9.81));

  text.replace(text.find("mass = 1.0"), 10, "mass = \"t_first\"");
  const std::string message = error_of(write("zero_g", text), {{"g", 0.0}});
  EXPECT_NE(message.find("bodies[0].mass: 't_first' is not finite (inf) for --set g=0"),
            std::string::npos)
      << message;
}

TEST_F(ScenarioHardening, DurationFormulaThatVanishesNamesTheParameter) {
  const fs::path path = scenario_directory() / "bouncing_ball.toml";
  const std::string message = error_of(path, {{"height", 0.1}});
  EXPECT_NE(message.find("duration: must be > 0 (got 0) for --set height=0.1"), std::string::npos)
      << message;
  // A duration given by the caller replaces the formula, which is then not evaluated.
  EXPECT_EQ(load_scenario(path, {{"height", 0.1}}, 0.5).duration, 0.5);
}

TEST_F(ScenarioHardening, AMalformedFileDurationIsRefusedEvenWhenTheFlagReplacesIt) {
  // The file's own value, line 6, whatever --duration says: what `describe` refuses, `run
  // --duration` refuses too.
  for (const std::string value : {"07:32:00", "0", "inf", "-0.0", "\"1/0\""}) {
    std::string text = minimal_scenario("bad_duration");
    text.replace(text.find("duration = 1.0"), 14, "duration = " + value);
    const fs::path path = write("bad_duration", text);
    const std::string without_flag = error_of(path);
    const std::string with_flag = error_of(path, {}, 0.5);
    EXPECT_NE(with_flag.find(path.string() + ":6: duration:"), std::string::npos)
        << value << ": " << with_flag;
    EXPECT_EQ(with_flag, without_flag) << value;
  }
}

}  // namespace
}  // namespace impactbench::scenario
