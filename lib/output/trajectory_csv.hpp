#pragma once
// The trajectory CSV of the design: header `t, <q names>, <v names>, energy`, then one row per
// output time, numbers in the shortest text that reads back exactly (csv_format.hpp). Written
// atomically: the file appears at commit() or never, so a run streaming its rows here and
// failing half-way leaves nothing behind.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/output/atomic_file.hpp"
#include "lib/output/trajectory.hpp"

namespace impactbench::output {

class TrajectoryCsvWriter {
 public:
  /// Opens the temporary file (throws std::runtime_error when it cannot be written); the
  /// header follows with write_header, when the engine has named its coordinates.
  explicit TrajectoryCsvWriter(const std::filesystem::path& path);
  TrajectoryCsvWriter(const std::filesystem::path& path,
                      const std::vector<std::string>& position_names,
                      const std::vector<std::string>& velocity_names);

  /// Writes the header; throws std::logic_error when called twice.
  void write_header(const std::vector<std::string>& position_names,
                    const std::vector<std::string>& velocity_names);
  bool has_header() const { return has_header_; }

  /// Throws std::invalid_argument if q or v do not match the column names, std::logic_error
  /// before the header.
  void write_row(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double energy);
  void write_row(const TrajectorySample& sample) {
    write_row(sample.t, sample.q, sample.v, sample.energy);
  }
  void commit() { file_.commit(); }
  AtomicFile& file() { return file_; }

 private:
  AtomicFile file_;
  bool has_header_ = false;
  std::size_t positions_ = 0;
  std::size_t velocities_ = 0;
  std::string line_;  // the row being built, reused
};

/// Header of a trajectory CSV for the given names.
std::vector<std::string> trajectory_columns(const std::vector<std::string>& position_names,
                                            const std::vector<std::string>& velocity_names);

/// Writes a whole trajectory atomically.
void write_trajectory_csv(const std::filesystem::path& path, const Trajectory& trajectory);

}  // namespace impactbench::output
