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

TrajectoryCsvWriter::TrajectoryCsvWriter(const std::filesystem::path& path) : file_(path) {}

TrajectoryCsvWriter::TrajectoryCsvWriter(const std::filesystem::path& path,
                                         const std::vector<std::string>& position_names,
                                         const std::vector<std::string>& velocity_names)
    : file_(path) {
  write_header(position_names, velocity_names);
}

void TrajectoryCsvWriter::write_header(const std::vector<std::string>& position_names,
                                       const std::vector<std::string>& velocity_names) {
  if (has_header_)
    throw std::logic_error("trajectory CSV " + file_.target().string() + ": header written twice");
  has_header_ = true;
  positions_ = position_names.size();
  velocities_ = velocity_names.size();
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
  if (!has_header_)
    throw std::logic_error("trajectory CSV " + file_.target().string() + ": row before header");
  if (static_cast<std::size_t>(q.size()) != positions_ ||
      static_cast<std::size_t>(v.size()) != velocities_)
    throw std::invalid_argument("trajectory row has " + std::to_string(q.size()) +
                                " positions and " + std::to_string(v.size()) +
                                " velocities, the header " + std::to_string(positions_) + " and " +
                                std::to_string(velocities_));
  // One write per row: a row of a pile holds thousands of numbers.
  line_.clear();
  append_number(line_, t);
  for (const double value : q) line_ += ',', append_number(line_, value);
  for (const double value : v) line_ += ',', append_number(line_, value);
  line_ += ',';
  append_number(line_, energy);
  line_ += '\n';
  file_.stream().write(line_.data(), static_cast<std::streamsize>(line_.size()));
}

void write_trajectory_csv(const std::filesystem::path& path, const Trajectory& trajectory) {
  TrajectoryCsvWriter writer(path, trajectory.position_names, trajectory.velocity_names);
  for (const auto& sample : trajectory.samples) writer.write_row(sample);
  writer.commit();
}

}  // namespace impactbench::output
