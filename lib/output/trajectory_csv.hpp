#pragma once
// The trajectory CSV of the design: header `t, <q names>, <v names>, energy`, then one row per
// output time, numbers with %.17g. Written atomically: the file appears at commit() or never.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/output/atomic_file.hpp"
#include "lib/output/trajectory.hpp"

namespace impactbench::output {

class TrajectoryCsvWriter {
 public:
  TrajectoryCsvWriter(const std::filesystem::path& path, std::vector<std::string> position_names,
                      std::vector<std::string> velocity_names);

  /// Throws std::invalid_argument if q or v do not match the column names.
  void write_row(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double energy);
  void write_row(const TrajectorySample& sample) {
    write_row(sample.t, sample.q, sample.v, sample.energy);
  }
  void commit() { file_.commit(); }

 private:
  AtomicFile file_;
  std::size_t positions_;
  std::size_t velocities_;
};

/// Header of a trajectory CSV for the given names.
std::vector<std::string> trajectory_columns(const std::vector<std::string>& position_names,
                                            const std::vector<std::string>& velocity_names);

/// Writes a whole trajectory atomically.
void write_trajectory_csv(const std::filesystem::path& path, const Trajectory& trajectory);

}  // namespace impactbench::output
