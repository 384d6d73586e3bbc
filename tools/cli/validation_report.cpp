#include "tools/cli/validation_report.hpp"

#include <map>
#include <sstream>

#include "lib/output/atomic_file.hpp"
#include "lib/output/csv_format.hpp"
#include "lib/output/number_text.hpp"
#include "lib/validation/score_statistics.hpp"

namespace impactbench::cli {
namespace {

const char* unit(const std::string& metric) {
  static const std::map<std::string, const char*> units = {
      {"position", "side"},          {"rotation", "rad"},    {"velocity", "m/s"},
      {"angular_velocity", "rad/s"}, {"rest_position", "m"}, {"rest_rotation", "rad"},
      {"first_contact_time", "s"}};
  return units.at(metric);
}

std::string cell(double value) {
  return output::number_text(value);
}

}  // namespace

std::string validation_summary(const ValidationHeader& header,
                               const std::vector<std::string>& engines,
                               const std::vector<TossRun>& runs) {
  const auto& names = validation::score_names();
  std::ostringstream md;
  md << "# Real tosses: engines against the recordings\n\n"
     << "Data `" << header.data << "`, tosses `" << header.selection << "`, initial state `"
     << header.initial_state << "`"
     << (header.overrides.empty() ? "" : ", parameters `" + header.overrides + "`") << "; "
     << cell(header.wall_seconds) << " s wall-clock.\n\n"
     << "| engine | scored | failed | metric | unit | mean | median | p90 |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  std::ostringstream failures;
  for (const std::string& engine : engines) {
    const EngineScores summed = engine_scores(runs, engine);
    for (const std::string& failure : summed.failures)
      failures << "- " << engine << ", " << failure << "\n";
    for (std::size_t m = 0; m < names.size(); ++m) {
      const validation::Statistics& s = summed.scores[m];
      md << "| " << engine << " | " << s.count << " | " << summed.failures.size() << " | "
         << names[m] << " | " << unit(names[m]) << " | " << cell(s.mean) << " | " << cell(s.median)
         << " | " << cell(s.p90) << " |\n";
    }
  }
  const std::string failed = failures.str();
  md << "\nFailed runs (counted above, not scored): " << (failed.empty() ? "none.\n" : "\n")
     << failed;
  return md.str();
}

void write_validation_outputs(const std::filesystem::path& out, const std::string& summary,
                              const std::vector<TossRun>& runs) {
  output::AtomicFile csv(out / "per_toss.csv");
  output::AtomicFile md(out / "summary.md");
  std::ostream& c = csv.stream();
  c << "engine,toss,status";
  for (const auto& name : validation::score_names()) c << ',' << name;
  c << ",wall_seconds,failure\n";
  for (const TossRun& run : runs) {
    output::write_text(c, run.engine);
    c << ',';
    output::write_text(c, run.toss);
    c << (run.failure.empty() ? ",scored" : ",failed");
    for (const double value : validation::score_values(run.score)) {
      c << ',';
      if (run.failure.empty()) output::write_number(c, value);
    }
    c << ',';
    output::write_number(c, run.wall_seconds);
    c << ',';
    output::write_text(c, run.failure);
    c << '\n';
  }
  md.stream() << summary;
  output::commit_together({&csv, &md});
}

}  // namespace impactbench::cli
