#include "tools/compare/equal_work_table.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <sstream>

#include "lib/output/table_csv.hpp"
#include "tools/compare/run_process.hpp"
#include "tools/compare/summary_format.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/equal_work.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::compare {
namespace {

constexpr double kDuration = 1.0;  // [s], 1,000 steps at the piles' dt
const double kNaN = std::numeric_limits<double>::quiet_NaN();

double cpu_ms_per_step(const EngineRow& row) {
  return 1e3 * named_value(row.values, "engine_cpu_seconds") / named_value(row.values, "steps");
}

double bare_ms_of(const EqualWorkOutcome& outcome, const std::string& engine) {
  const auto found = outcome.bare.find(engine);
  return found == outcome.bare.end() ? kNaN : found->second.ms_per_step;
}

// Why the engine's bare loop failed ("" if it ran or was not run).
std::string bare_failure_of(const EqualWorkOutcome& outcome, const std::string& engine) {
  const auto found = outcome.bare.find(engine);
  return found == outcome.bare.end() || found->second.failure.empty()
             ? std::string()
             : "bare loop failed: " + found->second.failure;
}

// The engine's bare loop with the options of its compared run (its failure is kept for the
// table; the compared run's figures still stand).
BareTiming bare_timing(const scenario::Scenario& s, const engines::RunOptions& options) {
  BareTiming timing;
  try {
    timing.ms_per_step = 1e3 * engines::bare_loop_seconds_per_step(s, options);
  } catch (const ProcessInterrupted&) {
    throw;
  } catch (const std::exception& error) {
    timing.failure = error.what();
    std::fprintf(stderr, "equal work %s: the bare loop of %s failed: %s\n", s.name.c_str(),
                 options.engine.c_str(), error.what());
  }
  return timing;
}

// The columns after scene and engine: (CSV name, Markdown header, metric or derived value).
struct Column {
  std::string csv, header;
};
const std::vector<Column>& columns() {
  static const std::vector<Column> list = {
      {"bare_cpu_ms_per_step", "engine CPU per step, bare loop [ms]"},
      {"moreau_over_engine", "Moreau–Jean ÷ engine (bare loops)"},
      {"recorded_cpu_ms_per_step", "engine CPU per step, recorded run [ms]"},
      {"steps", "steps"},
      {"unconverged_steps", "unconverged steps"},
      {"mean_contacts", "mean contacts"},
      {"max_penetration", "max penetration [m]"},
      {"signorini", "Signorini [N·m]"},
      {"complementarity", "complementarity [N·m]"},
      {"friction_cone", "friction cone [N·s]"},
      {"energy_max_rise", "energy max rise [J]"}};
  return list;
}

std::vector<double> row_values(const EqualWorkOutcome& outcome, const EngineRow& row) {
  const double ms = bare_ms_of(outcome, row.engine);
  std::vector<double> values = {ms, bare_ms_of(outcome, engine_name::kMoreau) / ms,
                                cpu_ms_per_step(row)};
  for (std::size_t c = values.size(); c < columns().size(); ++c)
    values.push_back(named_value(row.values, columns()[c].csv));
  return values;
}

}  // namespace

std::vector<EqualWorkCase> equal_work_cases(bool quick) {
  std::vector<EqualWorkCase> cases = {
      {"disk_pile, 1,000 disks", "disk_pile_1000", "disk_pile", {{"count", 1000}}}};
  if (quick) return cases;
  cases.push_back({"disk_pile, 10,000 disks, 100 m wide",
                   "disk_pile_10000_wide",
                   "disk_pile",
                   {{"count", 10000}, {"width", 100}}});
  cases.push_back(
      {"sphere_pile, 1,000 spheres", "sphere_pile_1000", "sphere_pile", {{"count", 1000}}});
  return cases;
}

EqualWorkOutcome run_equal_work(const EqualWorkCase& scene, const std::filesystem::path& out) {
  EqualWorkOutcome outcome{scene, {}, "", {}};
  try {
    const auto s = scenario::load_scenario_by_name(scene.scenario, scene.overrides);
    CompareOptions options;
    options.out = out;
    options.duration = kDuration;
    for (const auto& engine : compared_engines(s, {}))
      for (const auto& wanted : engines::equal_work_engines())
        if (engine == wanted) {
          options.engines.push_back(engine);
          options.settings[engine] = engines::equal_work_settings(engine);
        }
    outcome.report = run_compare(s, options);
    const std::vector<engines::RunOptions> runs = resolve_compare_runs(s, options);
    for (const EngineRow& row : outcome.report.rows)
      for (const engines::RunOptions& run : runs)
        if (row.failure.empty() && run.engine == row.engine)
          outcome.bare[row.engine] = bare_timing(s, run);
  } catch (const ProcessInterrupted&) {
    throw;  // an interrupt ends the suite; it is not this pile's failure
  } catch (const std::exception& error) {
    outcome.failure = error.what();
  }
  return outcome;
}

std::string equal_work_markdown(const std::vector<EqualWorkOutcome>& outcomes) {
  std::ostringstream md;
  md << "| scene | engine |";
  for (const auto& c : columns()) md << " " << c.header << " |";
  md << "\n|---|---|";
  for (std::size_t c = 0; c < columns().size(); ++c) md << "---:|";
  md << "\n";
  for (const auto& o : outcomes) {
    if (!o.failure.empty()) {
      md << "| " << o.scene.label << " | **failed** | " << markdown_cell(o.failure) << " |";
      for (std::size_t c = 1; c < columns().size(); ++c) md << " |";
      md << "\n";
      continue;
    }
    for (const auto& row : o.report.rows) {
      md << "| " << o.scene.label << " | " << row.engine << " |";
      if (!row.failure.empty()) {  // one engine failed, the others ran
        md << " **failed:** " << markdown_cell(row.failure) << " |";
        for (std::size_t c = 1; c < columns().size(); ++c) md << " |";
      } else {
        // A failed bare loop shows its reason in place of its time.
        const std::string bare_failure = bare_failure_of(o, row.engine);
        const std::vector<double> values = row_values(o, row);
        for (std::size_t c = 0; c < values.size(); ++c)
          md << " "
             << (c == 0 && !bare_failure.empty() ? "**" + markdown_cell(bare_failure) + "**"
                                                 : format_value(values[c]))
             << " |";
      }
      md << "\n";
    }
  }
  return md.str();
}

void write_equal_work_csv(const std::filesystem::path& csv,
                          const std::vector<EqualWorkOutcome>& outcomes) {
  output::Table table{{"scene", "engine"}, {}};
  for (const auto& c : columns()) table.columns.push_back(c.csv);
  table.columns.push_back("failure");
  const auto cell = [](double v) {
    return std::isnan(v) ? output::TableCell{std::string()} : output::TableCell{v};
  };
  for (const auto& o : outcomes) {
    if (!o.failure.empty()) {
      std::vector<output::TableCell> row = {o.scene.label, std::string()};
      for (std::size_t c = 0; c < columns().size(); ++c) row.push_back(std::string());
      row.push_back(o.failure);
      table.rows.push_back(std::move(row));
      continue;
    }
    for (const auto& r : o.report.rows) {
      std::vector<output::TableCell> row = {o.scene.label, r.engine};
      for (const double v : row_values(o, r)) row.push_back(cell(v));
      row.push_back(r.failure.empty() ? bare_failure_of(o, r.engine) : r.failure);
      table.rows.push_back(std::move(row));
    }
  }
  output::write_table_csv(csv, table);
}

}  // namespace impactbench::compare
