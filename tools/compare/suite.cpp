#include "tools/compare/suite.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "lib/output/atomic_file.hpp"
#include "lib/output/table_csv.hpp"
#include "tools/compare/benchmark_section.hpp"
#include "tools/compare/compare.hpp"
#include "tools/compare/equal_work_table.hpp"
#include "tools/compare/run_process.hpp"
#include "tools/compare/summary_format.hpp"
#include "tools/compare/work_precision.hpp"
#include "tools/engines/engine_names.hpp"
#include "tools/engines/registry/equal_work.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::compare {
namespace {

using Clock = std::chrono::steady_clock;

// Progress on stderr: "[  12 s] step 3/14: compare sliding_block".
class Progress {
 public:
  explicit Progress(int total) : total_(total), start_(Clock::now()) {}
  void step(const std::string& what) {
    ++done_;
    std::fprintf(stderr, "[%5.0f s] %d/%d %s\n", elapsed(), done_, total_, what.c_str());
  }
  void note(const std::string& what) const {
    std::fprintf(stderr, "[%5.0f s]      %s\n", elapsed(), what.c_str());
  }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  int total_;
  int done_ = 0;
  Clock::time_point start_;
};

// Piles are reduced so the default suite stays within its time budget; their full sizes are
// the benchmarks' business.
const std::map<std::string, scenario::ParameterOverrides>& pile_sizes() {
  static const std::map<std::string, scenario::ParameterOverrides> sizes = {
      {"disk_pile", {{"count", 60}}},
      {"sphere_pile", {{"count", 60}}},
      {"box_pyramid", {{"rows", 5}}}};
  return sizes;
}
constexpr double kPileDuration = 1.0;  // [s]

// The analytical scenarios with a work-precision diagram, and the quantity each measures.
const std::vector<std::pair<std::string, std::string>>& work_precision_cases() {
  static const std::vector<std::pair<std::string, std::string>> cases = {
      {"bouncing_ball", "apex_error"}, {"sliding_block", "stop_distance_error"}};
  return cases;
}

// The short version of each benchmark binary: a filter on its sizes and a minimum time.
const std::map<std::string, std::string>& benchmark_filters() {
  static const std::map<std::string, std::string> filters = {
      {"lcp_bench", "/(10|100)$"},
      {"friction_bench", "/(10|100)/"},
      // The fast solver-file pairs; spheres-in-a-box and Lemke take minutes.
      {"fclib_bench", "fclib/(prox-gs|nsgs|nsn)/(Box_Stacks|LMGC|Spheres-i)"},
      {"contact_detection_planar_bench", "/(100|1000)$"},
      {"contact_detection_spatial_bench", "/(100|1000)$"},
      // Lemke on the spatial pile (faceted cone, 1.6 s a step) would outlast the time limit.
      {"moreau_bench", "/(nsgs|prox-gs|prox-jacobi|nsn|pgs)/100/|disk_pile/lemke/100/"},
      {"event_bench", "bouncing_ball|sliding_block"},
      // Every engine stepping 1,000 disks for 1 s at equal work, five rounds (about 20 s of
      // CPU), and Moreau–Jean's allocations on the settled pile with nsgs and with prox-gs (3 s
      // each, about 4 s of CPU); 10,000 disks take minutes.
      {"equal_work_bench", "/disk_pile/1000/"},
  };
  return filters;
}

struct ScenarioOutcome {
  std::string name;
  std::string description;
  CompareReport report;
  std::string failure;
};

struct WorkPrecisionOutcome {
  std::string scenario, quantity, png;
  std::vector<WorkPoint> points;
};

// "moreau `solver=nsgs max_iterations=10 ...`; box2d `...`": what each engine was asked to do.
std::string equal_work_settings_text() {
  std::string text;
  for (const std::string& engine : engines::equal_work_engines()) {
    if (!text.empty()) text += "; ";
    text += engine + " `";
    std::string pairs;
    for (const auto& [key, value] : engines::equal_work_settings(engine))
      pairs += (pairs.empty() ? "" : " ") + key + "=" + value;
    text += pairs + "`";
  }
  return text;
}

// The "Real tosses" section: its Markdown, or why it failed.
struct RealTossesOutcome {
  std::string markdown;
  std::string failure;
};

void write_summary(const std::filesystem::path& path, const SuiteOptions& options,
                   const std::vector<ScenarioOutcome>& scenarios, const RealTossesOutcome& real,
                   const std::vector<WorkPrecisionOutcome>& work,
                   const std::vector<EqualWorkOutcome>& equal_work,
                   const std::vector<BenchmarkOutcome>& benchmarks, double seconds) {
  output::AtomicFile file(path);
  std::ostream& md = file.stream();
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  md << "# impactbench suite" << (options.quick ? " (quick)" : "") << "\n\n"
     << "Generated " << date << " in " << format_value(seconds) << " s. Errors are measured − "
     << "analytical (closed forms of each scenario file); `l1_error`/`linf_error` (positions, "
     << "[m·s] and [m]) and `l1_angle_error`/`linf_angle_error` (orientations as the angle of "
     << "the relative rotation, [rad·s] and [rad]) are against the reference trajectory named "
     << "per scenario. Per run, on this machine: "
     << "`engine_cpu_seconds` is the process CPU time of the engine's stepping alone, "
     << "`record_cpu_seconds` that of our recording (samples, contacts, events; for the "
     << "reference engines the adapter's work), `wall_seconds` the wall-clock time of both; "
        "`steps` the time "
     << "steps (event-driven: its flow integrator's steps), `unconverged_steps` the steps whose "
        "contact problem "
     << "was not solved to tolerance (a run may continue past them with on_failure=warn), "
     << "`mean_contacts` the contacts in the contact problem per step (event-driven: closed "
     << "contacts averaged over time), `max_penetration` the deepest penetration of any contact "
     << "in any recorded state. Box2D's boxes and boundaries are built with their polygon skin "
     << "inside the scenario's surfaces, so its heights are measured as reported. MuJoCo's "
        "contacts are soft: its bodies sink into contacts "
     << "(docs/reference-engines.md).\n\n";
  md << "## Scenarios\n\n"
     << "Each table's first row, `asked to run with`, is what each engine was asked to do: its "
        "step, tolerance, solver and iteration limits in force (every setting with its source is "
        "in the scenario's metrics.csv, column `settings`). Each reference engine has two "
        "columns: `ENGINE` at this benchmark's defaults and `ENGINE (expert)` at its expert "
        "settings, the values its own documentation gives for accurate rigid contact "
        "(docs/reference-engines.md#expert-settings); a run that failed says `failed` in its "
        "column and its reason below the table.\n\n";
  for (const auto& s : scenarios) {
    md << "### " << s.name << "\n\n" << s.description << "\n\n";
    if (!s.failure.empty()) {
      md << "**Failed:** " << s.failure << "\n\n";
      continue;
    }
    md << "Reference trajectory: " << s.report.reference << ".\n\n";
    if (s.report.rows.empty()) continue;
    md << "| metric |";
    for (const auto& row : s.report.rows) md << " " << row.engine << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < s.report.rows.size(); ++i) md << "---:|";
    md << "\n| asked to run with |";
    for (const auto& row : s.report.rows) md << " " << markdown_cell(row.asked) << " |";
    md << "\n";
    for (const auto& name : s.report.metric_names()) {
      md << "| " << name << " |";
      for (const auto& row : s.report.rows)
        md << " " << (row.failure.empty() ? format_value(named_value(row.values, name)) : "failed")
           << " |";
      md << "\n";
    }
    md << "\n";
    for (const auto& row : s.report.rows)
      if (!row.note.empty()) md << "- " << row.engine << ": " << row.note << ".\n";
    for (const auto& row : s.report.rows)
      if (!row.failure.empty())
        md << "- " << row.engine << ": **failed:** " << markdown_cell(row.failure) << "\n";
    md << "\n";
    for (const auto& png : s.report.plots)
      md << "![" << s.name << "](" << std::filesystem::relative(png, path.parent_path()).string()
         << ")\n";
    md << "\n";
  }
  if (real.failure.empty())
    md << real.markdown << "\n";
  else
    md << "## Real tosses\n\n**Failed:** " << markdown_cell(real.failure) << "\n\n";
  md << "## Work-precision diagrams\n\n"
     << "Error of one closed-form quantity against the engine's CPU time (its stepping alone): "
     << "Moreau–Jean, Box2D, Bullet, ODE and MuJoCo over step sizes, the event-driven integrator "
        "over "
     << "tolerances. A point whose run failed or has no such quantity is listed as failed.\n\n";
  for (const auto& w : work) {
    md << "### " << w.scenario << ": " << w.quantity << "\n\n";
    if (!w.png.empty()) md << "![" << w.scenario << "](" << w.png << ")\n\n";
    md << work_precision_markdown(w.points);
    md << "\n";
  }
  md << "## Piles at equal work\n\n"
     << "Each pile stepped for 1 s (1,000 steps) by every engine at equal work, with the "
        "settings the engine registry lists for it: "
     << equal_work_settings_text()
     << ". Moreau–Jean counts a step that ends above its tolerance in `unconverged steps` and "
        "goes on (`on_failure=warn`). `engine CPU per step, bare loop` is the process CPU time "
        "of the engine's stepping divided by the steps, in a second run of the same settings "
        "where nothing of ours runs between the engine's steps (a timing-only run); `Moreau–Jean "
        "÷ engine` is Moreau–Jean's bare-loop CPU per step over this engine's, in the same suite "
        "run (below 1: Moreau–Jean is faster). `engine CPU per step, recorded run` is the same "
        "time in the compared run, where our recording between the steps (not itself counted) "
        "evicts the engine's data from the caches. The accuracy columns are those of the "
        "recorded run (metrics.csv of each pile in `equal_work/`). Figures: "
        "[equal_work.csv](equal_work.csv).\n\n"
     << equal_work_markdown(equal_work) << "\n";
  md << benchmarks_markdown(options.bench_dir, benchmarks);
  file.commit();
}

}  // namespace

std::filesystem::path run_suite(const SuiteOptions& options) {
  std::filesystem::create_directories(options.out);
  const auto names = scenario::list_scenarios();
  std::vector<std::string> benches;
  if (!options.bench_dir.empty() && std::filesystem::is_directory(options.bench_dir))
    for (const auto& [name, filter] : benchmark_filters())
      if (std::filesystem::exists(options.bench_dir / name)) benches.push_back(name);

  const auto equal_work_scenes = equal_work_cases(options.quick);
  Progress progress(static_cast<int>(names.size() + 1 + work_precision_cases().size() +
                                     equal_work_scenes.size() + benches.size()));
  std::vector<ScenarioOutcome> scenarios;
  for (const auto& name : names) {
    const bool pile = pile_sizes().count(name) > 0;
    progress.step("compare " + name + (pile && options.quick ? " (skipped: --quick)" : ""));
    if (pile && options.quick) continue;
    ScenarioOutcome outcome{name, "", {}, ""};
    try {
      const auto s = scenario::load_scenario_by_name(
          name, pile ? pile_sizes().at(name) : scenario::ParameterOverrides{});
      outcome.description = s.description;
      CompareOptions c;
      c.out = options.out / name;
      c.python = options.python;
      c.tools_dir = options.tools_dir;
      // Each reference engine twice: at its defaults and at its expert set (its own
      // documentation's values), so that none is judged only at settings of ours.
      c.settings_sets = {engines::SettingsSet::kDefault, engines::SettingsSet::kExpert};
      if (pile) {
        c.duration = kPileDuration;
        // Gauss–Seidel does not reach the default 1e-10 on a settling pile within its sweep
        // limit; the pile runs continue with the best iterate and count the warnings.
        c.settings[engine_name::kMoreau] = {{"on_failure", "warn"}, {"max_iterations", "200"}};
      }
      if (options.quick) c.duration = std::min(s.duration, 3.0);
      outcome.report = run_compare(s, c);
    } catch (const ProcessInterrupted&) {
      throw;  // Ctrl-C during a plot ends the suite, as during a benchmark
    } catch (const std::exception& e) {
      outcome.failure = e.what();
      progress.note("failed: " + outcome.failure);
    }
    scenarios.push_back(std::move(outcome));
  }

  progress.step(
      std::string("real tosses (validate at the default and the fitted parameters, test split") +
      (options.quick ? ", the first 10)" : ")"));
  RealTossesOutcome real;
  try {
    if (!options.real_tosses) throw std::logic_error("suite: no real-tosses runner");
    real.markdown =
        options.real_tosses(options.quick, options.out / "real_tosses", !options.python.empty());
  } catch (const ProcessInterrupted&) {
    throw;
  } catch (const std::exception& e) {
    real.failure = e.what();
    progress.note("failed: " + real.failure);
  }

  std::vector<WorkPrecisionOutcome> work;
  for (const auto& [name, quantity] : work_precision_cases()) {
    progress.step("work-precision " + name + " (" + quantity + ")");
    const auto s = scenario::load_scenario_by_name(name);
    WorkPrecisionOutcome w{name, quantity, "", {}};
    if (!options.work_precision) throw std::logic_error("suite: no work-precision runner");
    w.points =
        options.work_precision(s, quantity, options.quick, options.out / "work_precision" / name,
                               [&](const std::string& text) { progress.note(text); });
    output::Table table{{"engine", "setting", "value", "error", "engine_cpu_seconds", "failure"},
                        {}};
    for (const auto& p : w.points) {
      auto number = [](double v) {
        return std::isnan(v) ? output::TableCell{std::string()} : output::TableCell{v};
      };
      table.rows.push_back(
          {p.engine, p.setting, p.value, number(p.error), number(p.engine_cpu_seconds), p.failure});
    }
    const auto csv = options.out / ("work_precision_" + name + ".csv");
    output::write_table_csv(csv, table);
    if (!options.python.empty() && !w.points.empty()) {
      const std::string png = "work_precision_" + name + ".png";
      if (run_process(
              {options.python.string(), (options.tools_dir / "plot_work_precision.py").string(),
               csv.string(), (options.out / png).string(), name + ": " + quantity + " vs CPU time"},
              {options.out / png}) == 0)
        w.png = png;
      else
        progress.note("work-precision plot failed for " + name);
    }
    work.push_back(std::move(w));
  }

  std::vector<EqualWorkOutcome> equal_work;
  for (const EqualWorkCase& scene : equal_work_scenes) {
    progress.step("equal work: " + scene.label);
    equal_work.push_back(run_equal_work(scene, options.out / "equal_work" / scene.directory));
    if (!equal_work.back().failure.empty()) progress.note("failed: " + equal_work.back().failure);
  }
  write_equal_work_csv(options.out / "equal_work.csv", equal_work);

  std::vector<BenchmarkOutcome> benchmarks;
  std::filesystem::create_directories(options.out / "bench");
  for (const auto& name : benches) {
    progress.step("benchmark " + name + " (short)");
    const std::string csv = "bench/" + name + ".csv";
    const std::string json = "bench/" + name + ".json";
    // A benchmark that outgrows its short version is cut off rather than stalling the suite.
    const std::string limit = options.quick ? "60" : "120";
    const int status = run_process(
        {"timeout", limit, (options.bench_dir / name).string(),
         "--benchmark_filter=" + benchmark_filters().at(name),
         options.quick ? "--benchmark_min_time=0.01" : "--benchmark_min_time=0.05",
         "--benchmark_out=" + (options.out / json).string(), "--benchmark_out_format=json"},
        {options.out / json});
    // Google Benchmark's own CSV reporter aborts when runs carry different counters: write JSON
    // and flatten it (every counter a column) with tools/benchmark_to_csv.py.
    const int converted =
        status == 0 ? run_process({options.python_for_scripts.string(),
                                   (options.tools_dir / "benchmark_to_csv.py").string(),
                                   (options.out / json).string(), (options.out / csv).string()},
                                  {options.out / csv})
                    : status;
    benchmarks.push_back({name, csv,
                          status == 124    ? "timed out after " + limit + " s"
                          : status != 0    ? "exit status " + std::to_string(status)
                          : converted != 0 ? "JSON to CSV conversion failed"
                                           : ""});
  }

  const auto summary = options.out / "summary.md";
  write_summary(summary, options, scenarios, real, work, equal_work, benchmarks,
                progress.elapsed());
  std::fprintf(stderr, "[%5.0f s] wrote %s\n", progress.elapsed(), summary.string().c_str());
  return summary;
}

}  // namespace impactbench::compare
