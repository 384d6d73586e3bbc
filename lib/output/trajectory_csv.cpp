#include "lib/output/trajectory_csv.hpp"

#include <stdexcept>

#include "lib/output/csv_format.hpp"

namespace impactbench::output {

std::vector<std::string> trajectory_columns(const std::vector<std::string>& position_names,
                                            const std::vector<std::string>& velocity_names) {
  std::vector<std::string> columns{"t"};
  columns.insert(columns.end(), position_names.begin(), position_names.end());
  columns.insert(columns.end(), velocity_names.begin(), velocity_names.end());
  columns.push_back("energy");
  return columns;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(const std::filesystem::path& path,
                                         std::vector<std::string> position_names,
                                         std::vector<std::string> velocity_names)
    : file_(path), positions_(position_names.size()), velocities_(velocity_names.size()) {
  const auto columns = trajectory_columns(position_names, velocity_names);
  auto& out = file_.stream();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i > 0) out << ',';
    write_text(out, columns[i]);
  }
  out << '\n';
}

void TrajectoryCsvWriter::write_row(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                                    double energy) {
  if (static_cast<std::size_t>(q.size()) != positions_ ||
      static_cast<std::size_t>(v.size()) != velocities_)
    throw std::invalid_argument("trajectory row has " + std::to_string(q.size()) +
                                " positions and " + std::to_string(v.size()) +
                                " velocities, the header " + std::to_string(positions_) + " and " +
                                std::to_string(velocities_));
  auto& out = file_.stream();
  write_number(out, t);
  for (const double value : q) out << ',', write_number(out, value);
  for (const double value : v) out << ',', write_number(out, value);
  out << ',';
  write_number(out, energy);
  out << '\n';
}

void write_trajectory_csv(const std::filesystem::path& path, const Trajectory& trajectory) {
  TrajectoryCsvWriter writer(path, trajectory.position_names, trajectory.velocity_names);
  for (const auto& sample : trajectory.samples) writer.write_row(sample);
  writer.commit();
}

}  // namespace impactbench::output
