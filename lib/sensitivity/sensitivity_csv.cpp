#include "lib/sensitivity/sensitivity_csv.hpp"

#include "lib/output/atomic_file.hpp"
#include "lib/sensitivity/reported_coordinates.hpp"

#include <functional>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace impactbench::sensitivity {
namespace {

void write_matrix(std::ostream& out, const std::string& prefix, const std::string& name,
                  const Eigen::MatrixXd& matrix) {
  for (Eigen::Index i = 0; i < matrix.rows(); ++i)
    for (Eigen::Index j = 0; j < matrix.cols(); ++j)
      out << prefix << ',' << name << ',' << i << ',' << j << ',' << matrix(i, j) << '\n';
}

std::string join(const std::vector<int>& order) {
  std::string text;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0) text += ' ';
    text += std::to_string(order[i]);
  }
  return text;
}

/// All-or-nothing file output (lib/output/atomic_file.hpp).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  output::AtomicFile file(path);
  write(file.stream());
  file.commit();
}

}  // namespace

void write_sensitivity_csv(std::ostream& out, const TrajectorySensitivity& sensitivity,
                           const EndPointSensitivity& end_point) {
  out << std::setprecision(17);
  out << "kind,event,t,order,micro_events,matrix,row,col,value\n";
  const HybridModel& model = sensitivity.model();
  const auto& events = sensitivity.events();
  for (std::size_t k = 0; k < events.size(); ++k) {
    const double t = sensitivity.nominal().events[k].time;
    for (const ComposedGain& gain : events[k].all_gains()) {
      std::string names;
      for (std::size_t i = 0; i < gain.order.size(); ++i) {
        if (i > 0) names += ' ';
        names += to_string(events[k].events()[gain.order[i]]);
      }
      std::ostringstream prefix;
      prefix << std::setprecision(17) << "jump_gain," << k << ',' << t << ',' << join(gain.order)
             << ',' << names;
      const ComposedGain reported = reported_gain(model, events[k], gain);
      write_matrix(out, prefix.str(), "Gz", reported.Gz);
      write_matrix(out, prefix.str(), "Gv", reported.Gv);
    }
  }
  std::ostringstream prefix;
  prefix << std::setprecision(17) << "end_point,-1," << sensitivity.nominal().t_end << ",,";
  const EndPointSensitivity reported = reported_end_point(sensitivity, end_point);
  write_matrix(out, prefix.str(), "state", reported.state);
  write_matrix(out, prefix.str(), "input", reported.input);
}

void write_sensitivity_csv_file(const std::filesystem::path& path,
                                const TrajectorySensitivity& sensitivity,
                                const EndPointSensitivity& end_point) {
  write_atomically(path,
                   [&](std::ostream& out) { write_sensitivity_csv(out, sensitivity, end_point); });
}

void write_prediction_csv(std::ostream& out, const PredictionSeries& series) {
  const std::size_t count = series.times.size();
  const auto n = static_cast<Eigen::Index>(series.state_names.size());
  if (series.nominal.size() != count || series.perturbed.size() != count ||
      series.predicted.size() != count)
    throw std::invalid_argument("write_prediction_csv: one state per time is needed");
  for (std::size_t i = 0; i < count; ++i)
    if (series.nominal[i].size() != n || series.perturbed[i].size() != n ||
        series.predicted[i].size() != n)
      throw std::invalid_argument("write_prediction_csv: states must have one entry per name");
  out << std::setprecision(17) << 't';
  for (const char* kind : {"nominal", "perturbed", "predicted"})
    for (const std::string& name : series.state_names) out << ',' << kind << '.' << name;
  out << '\n';
  for (std::size_t i = 0; i < count; ++i) {
    out << series.times[i];
    for (const auto* states : {&series.nominal, &series.perturbed, &series.predicted})
      for (Eigen::Index j = 0; j < n; ++j) out << ',' << (*states)[i](j);
    out << '\n';
  }
}

void write_prediction_csv_file(const std::filesystem::path& path, const PredictionSeries& series) {
  write_atomically(path, [&](std::ostream& out) { write_prediction_csv(out, series); });
}

void write_sensitivity_outputs(const std::filesystem::path& gains_path,
                               const TrajectorySensitivity& sensitivity,
                               const EndPointSensitivity& end_point,
                               const std::filesystem::path* prediction_path,
                               const PredictionSeries* series) {
  output::AtomicFile gains(gains_path);
  write_sensitivity_csv(gains.stream(), sensitivity, end_point);
  if (prediction_path == nullptr || series == nullptr) return gains.commit();
  output::AtomicFile prediction(*prediction_path);
  write_prediction_csv(prediction.stream(), *series);
  output::commit_together({&gains, &prediction});
}

}  // namespace impactbench::sensitivity
