#include "tools/cli/validation_report.hpp"

#include <map>
#include <sstream>

#include "lib/output/atomic_file.hpp"
#include "lib/output/csv_format.hpp"
#include "lib/output/number_text.hpp"
#include "lib/validation/error_over_time.hpp"
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

void write_per_toss(std::ostream& c, const std::vector<TossRun>& runs) {
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
}

void write_statistics(std::ostream& c, const validation::Statistics& s) {
  for (const double value : {s.mean, s.median, s.p90}) {
    c << ',';
    output::write_number(c, value);
  }
}

void write_error_over_time(std::ostream& c, const std::vector<std::string>& engines,
                           const std::vector<TossRun>& runs) {
  c << "engine,time_s,bin_width_s,tosses,position_mean,position_median,position_p90,"
       "rotation_mean,rotation_median,rotation_p90\n";
  for (const std::string& engine : engines) {
    std::vector<std::vector<validation::SampleError>> tosses;
    for (const TossRun& run : runs)
      if (run.engine == engine && run.failure.empty()) tosses.push_back(run.errors);
    for (const validation::ErrorBin& bin : validation::error_over_time(tosses, kErrorBinSeconds)) {
      output::write_text(c, engine);
      c << ',';
      output::write_number(c, bin.start);
      c << ',';
      output::write_number(c, kErrorBinSeconds);
      c << ',' << bin.position.count;
      write_statistics(c, bin.position);
      write_statistics(c, bin.rotation);
      c << '\n';
    }
  }
}

void write_pose_row(std::ostream& c, const std::string& source, const std::string& toss, double t,
                    const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  output::write_text(c, source);
  c << ',';
  output::write_text(c, toss);
  for (const double value : {t, p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z()}) {
    c << ',';
    output::write_number(c, value);
  }
  c << '\n';
}

void write_toss_trajectory(std::ostream& c, const std::vector<TossRun>& runs,
                           const validation::Toss& traced) {
  c << "source,toss,t,x,y,z,qw,qx,qy,qz\n";
  for (const auto& sample : traced.samples)
    write_pose_row(c, "data", traced.name, sample.t, sample.position, sample.orientation);
  for (const TossRun& run : runs) {
    if (run.toss != traced.name || !run.failure.empty()) continue;
    for (std::size_t i = 0; i < run.poses.size() && i < traced.samples.size(); ++i)
      write_pose_row(c, run.engine, traced.name, traced.samples[i].t, run.poses[i].position,
                     run.poses[i].orientation);
  }
}

}  // namespace

const std::vector<std::string>& validation_output_names() {
  static const std::vector<std::string> names = {"per_toss.csv", "summary.md",
                                                 "error_over_time.csv", "toss_trajectory.csv"};
  return names;
}

std::string validation_summary(const ValidationHeader& header,
                               const std::vector<std::string>& engines,
                               const std::vector<TossRun>& runs) {
  const auto& names = validation::score_names();
  std::ostringstream md;
  md << "# Real tosses: engines against the recordings, "
     << (header.parameter_set == "default" ? std::string("default parameters")
                                           : "parameter set " + header.parameter_set)
     << "\n\n"
     << "Data `" << header.data << "`, tosses `" << header.selection << "`, initial state `"
     << header.initial_state << "`, parameter set `" << header.parameter_set << "`"
     << (header.table.empty() ? "" : " (" + header.table + ")")
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
                              const std::vector<std::string>& engines,
                              const std::vector<TossRun>& runs, const validation::Toss& traced) {
  const auto& names = validation_output_names();
  output::AtomicFile csv(out / names[0]);
  output::AtomicFile md(out / names[1]);
  output::AtomicFile over_time(out / names[2]);
  output::AtomicFile trajectory(out / names[3]);
  write_per_toss(csv.stream(), runs);
  md.stream() << summary;
  write_error_over_time(over_time.stream(), engines, runs);
  write_toss_trajectory(trajectory.stream(), runs, traced);
  output::commit_together({&csv, &md, &over_time, &trajectory});
}

}  // namespace impactbench::cli
