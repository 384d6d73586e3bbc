#include "tools/compare/equal_work_table.hpp"

#include <cmath>
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

// The columns after scene and engine: (CSV name, Markdown header, metric or derived value).
struct Column {
  std::string csv, header;
};
const std::vector<Column>& columns() {
  static const std::vector<Column> list = {
      {"engine_cpu_ms_per_step", "engine CPU per step [ms]"},
      {"moreau_over_engine", "Moreau–Jean ÷ engine (CPU per step)"},
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

std::vector<double> row_values(const EngineRow& row, double moreau_ms) {
  const double ms = cpu_ms_per_step(row);
  std::vector<double> values = {ms, moreau_ms / ms};
  for (std::size_t c = 2; c < columns().size(); ++c)
    values.push_back(named_value(row.values, columns()[c].csv));
  return values;
}

double moreau_ms_of(const CompareReport& report) {
  for (const auto& row : report.rows)
    if (row.engine == engine_name::kMoreau) return cpu_ms_per_step(row);
  return kNaN;
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
  EqualWorkOutcome outcome{scene, {}, ""};
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
    const double moreau_ms = moreau_ms_of(o.report);
    for (const auto& row : o.report.rows) {
      md << "| " << o.scene.label << " | " << row.engine << " |";
      if (!row.failure.empty()) {  // one engine failed, the others ran
        md << " **failed:** " << markdown_cell(row.failure) << " |";
        for (std::size_t c = 1; c < columns().size(); ++c) md << " |";
      } else {
        for (const double v : row_values(row, moreau_ms)) md << " " << format_value(v) << " |";
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
    const double moreau_ms = moreau_ms_of(o.report);
    for (const auto& r : o.report.rows) {
      std::vector<output::TableCell> row = {o.scene.label, r.engine};
      for (const double v : row_values(r, moreau_ms)) row.push_back(cell(v));
      row.push_back(r.failure);
      table.rows.push_back(std::move(row));
    }
  }
  output::write_table_csv(csv, table);
}

}  // namespace impactbench::compare
