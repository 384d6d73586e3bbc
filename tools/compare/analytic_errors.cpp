#include "tools/compare/analytic_errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/metrics/ballistic_events.hpp"

namespace impactbench::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One column of a run's trajectory, by CSV name (positions first, then velocities).
std::vector<double> column(const engines::RunResult& run, const std::string& name) {
  std::vector<double> values;
  const auto find = [&](const std::vector<std::string>& names) {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  };
  const output::Trajectory& trajectory = run.trajectory;
  if (const int i = find(trajectory.position_names); i >= 0) {
    for (const auto& sample : trajectory.samples) values.push_back(sample.q[i]);
  } else if (const int j = find(trajectory.velocity_names); j >= 0) {
    for (const auto& sample : trajectory.samples) values.push_back(sample.v[j]);
  } else {
    throw std::invalid_argument("run of engine '" + run.engine + "' has no column '" + name + "'");
  }
  return values;
}

std::vector<double> sample_times(const engines::RunResult& run) {
  std::vector<double> times;
  for (const auto& sample : run.trajectory.samples) times.push_back(sample.t);
  return times;
}

double worst(double current, double error) {
  if (std::isnan(error)) return kNaN;
  if (std::isnan(current)) return current;
  return std::abs(error) > std::abs(current) ? error : current;
}

void bounce_errors(const scenario::Scenario& s, const engines::RunResult& run, NamedValues& out) {
  const std::string body = s.bodies.front().name;
  const bool planar = s.dimension == scenario::Dimension::kPlanar;
  const auto times = sample_times(run);
  const auto height = column(run, body + (planar ? ".y" : ".z"));
  const auto vertical = column(run, body + (planar ? ".vy" : ".vz"));
  if (s.has_analytic("apex")) {
    const auto apexes = metrics::apex_heights(times, height);
    double error = 0.0;
    for (int k = 1; k <= kCheckedBounces; ++k)
      error = worst(error, k <= static_cast<int>(apexes.size())
                               ? apexes[k - 1].height - s.analytic("apex", k)
                               : kNaN);
    out.emplace_back("apex_error", error);
  }
  if (s.has_analytic("impact_time")) {
    const auto impacts = metrics::impact_times(times, vertical, 1e-6);
    double error = 0.0;
    for (int k = 0; k < kCheckedBounces; ++k)
      error = worst(error, k < static_cast<int>(impacts.size())
                               ? impacts[k] - s.analytic("impact_time", k)
                               : kNaN);
    out.emplace_back("impact_time_error", error);
  }
  if (s.has_analytic("t_inf")) {
    // Only an engine that predicts the accumulation point reports it (a zeno_limit event).
    const auto limit =
        std::find_if(run.events.begin(), run.events.end(),
                     [](const output::EventRecord& e) { return e.kind == "zeno_limit"; });
    out.emplace_back("accumulation_time_error",
                     limit == run.events.end() ? kNaN : limit->t - s.analytic("t_inf"));
  }
}

void stop_errors(const scenario::Scenario& s, const engines::RunResult& run, NamedValues& out) {
  const std::string body = s.bodies.front().name;
  const auto x = column(run, body + ".x");
  const auto vx = column(run, body + ".vx");
  // Below 10 µm/s a float engine's sliding body is at rest; the stop-time bias is ~2 µs.
  const auto stop = metrics::stop_point(sample_times(run), x, vx, 1e-5);
  out.emplace_back("stop_time_error", stop ? stop->t - s.analytic("stop_time") : kNaN);
  out.emplace_back("stop_distance_error",
                   stop ? stop->position - x.front() - s.analytic("stop_distance") : kNaN);
}

void final_value_errors(const scenario::Scenario& s, const engines::RunResult& run,
                        NamedValues& out) {
  const std::string body = s.bodies.front().name;
  if (s.has_analytic("slip_speed") && s.has_analytic("slip_distance")) {  // pushed block
    const auto vx = column(run, body + ".vx"), vy = column(run, body + ".vy");
    out.emplace_back("slip_speed_error",
                     std::hypot(vx.back(), vy.back()) - s.analytic("slip_speed"));
  }
  if (s.has_analytic("final_vx") && s.has_analytic("final_vy")) {  // spinning sphere
    const auto vx = column(run, body + ".vx"), vy = column(run, body + ".vy");
    out.emplace_back("final_velocity_error", std::hypot(vx.back() - s.analytic("final_vx"),
                                                        vy.back() - s.analytic("final_vy")));
  }
  if (s.has_analytic("final_speed_last")) {  // cradle
    const auto v_last = column(run, s.bodies.back().name + ".vx");
    out.emplace_back("final_speed_error", v_last.back() - s.analytic("final_speed_last"));
  }
}

}  // namespace

double named_value(const NamedValues& values, const std::string& name) {
  for (const auto& [key, value] : values)
    if (key == name) return value;
  return std::numeric_limits<double>::quiet_NaN();
}

NamedValues analytic_errors(const scenario::Scenario& scenario, const engines::RunResult& run) {
  NamedValues errors;
  if (scenario.bodies.empty() || run.trajectory.samples.empty()) return errors;
  if (scenario.has_analytic("apex")) bounce_errors(scenario, run, errors);
  if (scenario.has_analytic("stop_time") && scenario.has_analytic("stop_distance"))
    stop_errors(scenario, run, errors);
  final_value_errors(scenario, run, errors);
  return errors;
}

}  // namespace impactbench::compare
