// The expert settings set (`--settings expert`): each reference engine's values from its own
// documentation, resolved over its defaults with the source "expert", under the scenario file
// and the command line; our own engines have none and keep their defaults. The expected values
// are written out here and in docs/reference-engines.md (#expert-settings), whose tables are
// read back and held to the code.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tools/engines/registry/engine_registry.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench {
namespace {

using engines::SettingSource;
using engines::SettingsSet;
using Values = std::map<std::string, std::string>;

// What each expert set must resolve to (the step, dt or timestep, stays the scenario's).
const std::map<std::string, Values>& expected_sets() {
  static const std::map<std::string, Values> sets = {
      {"box2d",
       {{"velocity_iterations", "50"},
        {"position_iterations", "20"},
        {"restitution_threshold", "0.001"}}},
      {"bullet",
       {{"solver", "si"},
        {"solver_iterations", "20"},
        {"split_impulse", "true"},
        {"split_impulse_depth", "0"},
        {"erp", "0.2"},
        {"restitution_threshold", "0.001"}}},
      {"ode",
       {{"stepper", "exact"},
        {"quick_iterations", "50"},
        {"erp", "0.2"},
        {"cfm", "1e-10"},
        {"friction", "pyramid"},
        {"bounce_velocity", "0.001"}}},
      {"mujoco",
       {{"solver", "newton"},
        {"cone", "elliptic"},
        {"impratio", "5"},
        {"noslip_iterations", "0"},
        {"iterations", "100"},
        {"solimp_dmin", "0.99"},
        {"solimp_dmax", "0.99"},
        {"solimp_width", "0.001"},
        {"solref_timeconst", "auto"},
        {"solref_dampratio", "restitution"}}},
  };
  return sets;
}

engines::RunOptions resolve(const std::string& engine, const std::string& scenario_name,
                            SettingsSet set, engines::SettingsRequest request = {}) {
  request.set = set;
  return engines::resolve_run_options(engine, scenario::load_scenario_by_name(scenario_name),
                                      request);
}

const engines::SettingValue& setting(const engines::RunOptions& options, const std::string& key) {
  for (const auto& s : options.settings)
    if (s.key == key) return s;
  throw std::out_of_range("no setting " + key);
}

TEST(ExpertSettings, ResolveToTheDocumentedValuesWithSourceExpert) {
  for (const auto& [engine, values] : expected_sets()) {
    SCOPED_TRACE(engine);
    EXPECT_TRUE(engines::applies_settings_set(engine, SettingsSet::kExpert));
    const auto options = resolve(engine, "bouncing_ball", SettingsSet::kExpert);
    EXPECT_EQ(options.settings_set, SettingsSet::kExpert);
    for (const auto& s : options.settings) {
      const auto it = values.find(s.key);
      if (it == values.end()) {
        EXPECT_NE(s.source, SettingSource::kExpert) << s.key;
        continue;
      }
      EXPECT_EQ(s.value, it->second) << s.key;
      EXPECT_EQ(engines::to_string(s.source), "expert") << s.key;
    }
    std::size_t from_set = 0;
    for (const auto& s : options.settings) from_set += s.source == SettingSource::kExpert;
    EXPECT_EQ(from_set, values.size());
  }
}

TEST(ExpertSettings, LeaveTheStepToTheScenario) {
  EXPECT_EQ(setting(resolve("box2d", "rocking_block", SettingsSet::kExpert), "dt").value, "1e-4");
  const auto mujoco = resolve("mujoco", "rocking_block", SettingsSet::kExpert);
  EXPECT_EQ(setting(mujoco, "timestep").value, "1e-4");
  EXPECT_EQ(setting(mujoco, "timestep").source, SettingSource::kScenario);
  EXPECT_EQ(setting(mujoco, "tolerance").source, SettingSource::kScenario);
}

TEST(ExpertSettings, TheScenarioFileOverridesTheSet) {
  // box_pyramid's [settings.ode] stepper = "quick" wins over the set's exact step.
  const auto ode = resolve("ode", "box_pyramid", SettingsSet::kExpert);
  EXPECT_EQ(setting(ode, "stepper").value, "quick");
  EXPECT_EQ(setting(ode, "stepper").source, SettingSource::kScenario);
  EXPECT_EQ(setting(ode, "cfm").value, "1e-10");
  EXPECT_EQ(setting(ode, "cfm").source, SettingSource::kExpert);
}

TEST(ExpertSettings, TheCommandLineOverridesTheSet) {
  engines::SettingsRequest request;
  request.options = {{"impratio", "3"}};
  request.solver = "cg";
  request.dt = 5e-4;
  const auto mujoco = resolve("mujoco", "sliding_block", SettingsSet::kExpert, request);
  EXPECT_EQ(setting(mujoco, "impratio").value, "3");
  EXPECT_EQ(setting(mujoco, "impratio").source, SettingSource::kCommandLine);
  EXPECT_EQ(setting(mujoco, "solver").value, "cg");
  EXPECT_EQ(setting(mujoco, "solver").source, SettingSource::kCommandLine);
  EXPECT_EQ(setting(mujoco, "timestep").value, "5e-4");
  EXPECT_EQ(setting(mujoco, "cone").source, SettingSource::kExpert);
}

TEST(ExpertSettings, OurEnginesHaveNoneAndKeepTheirDefaults) {
  for (const std::string engine : {"moreau", "event", "siconos"}) {
    SCOPED_TRACE(engine);
    EXPECT_FALSE(engines::applies_settings_set(engine, SettingsSet::kExpert));
    const auto expert = resolve(engine, "bouncing_ball", SettingsSet::kExpert);
    const auto defaults = resolve(engine, "bouncing_ball", SettingsSet::kDefault);
    ASSERT_EQ(expert.settings.size(), defaults.settings.size());
    for (std::size_t i = 0; i < expert.settings.size(); ++i) {
      EXPECT_EQ(expert.settings[i].key, defaults.settings[i].key);
      EXPECT_EQ(expert.settings[i].value, defaults.settings[i].value);
      EXPECT_EQ(expert.settings[i].source, defaults.settings[i].source);
    }
  }
}

TEST(ExpertSettings, EveryReferenceEngineHasOneAndOursNone) {
  std::vector<std::string> with_set;
  for (const auto& info : adapters::engine_registry())
    if (!info.settings->expert.empty()) with_set.push_back(info.name);
  EXPECT_EQ(with_set, (std::vector<std::string>{"box2d", "bullet", "ode", "mujoco"}));
  for (const auto& [engine, values] : expected_sets())
    EXPECT_EQ(engines::find_engine_settings(engine)->expert.size(), values.size()) << engine;
}

TEST(ExpertSettings, UnknownSetNameIsRefused) {
  EXPECT_EQ(engines::parse_settings_set("expert"), SettingsSet::kExpert);
  EXPECT_EQ(engines::parse_settings_set("default"), SettingsSet::kDefault);
  try {
    engines::parse_settings_set("experts");
    FAIL() << "accepted 'experts'";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "unknown settings set 'experts' (sets: default or expert)");
  }
}

// docs/reference-engines.md, section "Expert settings": one table per engine under a heading
// "### Title (`engine`)", rows "| `key` | default | expert | source | why |".
std::map<std::string, std::map<std::string, std::pair<std::string, std::string>>> docs_tables() {
  std::ifstream in(std::filesystem::path(IMPACTBENCH_TEST_DATA_DIR) / ".." / ".." / "docs" /
                   "reference-engines.md");
  std::map<std::string, std::map<std::string, std::pair<std::string, std::string>>> tables;
  bool in_section = false;
  std::string engine;
  const auto unquote = [](std::string cell) {
    const auto first = cell.find_first_not_of(" `");
    const auto last = cell.find_last_not_of(" `");
    return first == std::string::npos ? std::string() : cell.substr(first, last - first + 1);
  };
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## Expert settings";
    if (!in_section) continue;
    if (line.rfind("### ", 0) == 0) {
      const auto open = line.find("(`");
      engine = open == std::string::npos ? "" : line.substr(open + 2, line.find("`)") - open - 2);
    } else if (!engine.empty() && line.rfind("| `", 0) == 0) {
      std::vector<std::string> cells;
      std::stringstream row(line.substr(1));
      for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
      if (cells.size() >= 3)
        tables[engine][unquote(cells[0])] = {unquote(cells[1]), unquote(cells[2])};
    }
  }
  return tables;
}

TEST(ExpertSettings, TheDocumentedTablesAreTheCode) {
  const auto tables = docs_tables();
  ASSERT_EQ(tables.size(), expected_sets().size()) << "engines with a table in the docs";
  for (const auto& [engine, values] : expected_sets()) {
    SCOPED_TRACE(engine);
    ASSERT_EQ(tables.count(engine), 1u);
    const auto& table = tables.at(engine);
    EXPECT_EQ(table.size(), values.size());
    const auto defaults = resolve(engine, "bouncing_ball", SettingsSet::kDefault);
    for (const auto& [key, value] : values) {
      ASSERT_EQ(table.count(key), 1u) << key << " has no row";
      EXPECT_EQ(table.at(key).second, value) << key;
      EXPECT_EQ(table.at(key).first, setting(defaults, key).value) << key << " (default)";
    }
  }
}

}  // namespace
}  // namespace impactbench
