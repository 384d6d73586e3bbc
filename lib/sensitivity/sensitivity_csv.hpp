#pragma once
// CSV output of the sensitivity module (long format, one matrix entry per row, so that gains of
// different shapes share one file):
//     kind,event,t,order,micro_events,matrix,row,col,value
// kind "jump_gain": for every macro event and every order of its micro events, the entries of
// Gz (n × n) and Gv (n × m); `order` lists micro-event indices separated by spaces, and
// `micro_events` names them ("0:impact->slip+ 1:impact->slip+"). kind "end_point": the entries
// of the end-point matrices "state" (n × n) and "input" (n × p), with event = -1 and t = t_end.
// Models with tangent coordinates (spatial bodies) write every matrix in them: row and column
// indices count, per body, δx δy δz, the world rotation vector δθx δθy δθz, then per body
// δvx δvy δvz δωx δωy δωz, then μ and e when they are states (HybridModel::tangent_basis).
//
// The prediction CSV holds, per output time, the nominal, perturbed and first-order predicted
// states, for tools/plot_sensitivity.py:
//     t,nominal.<name>...,perturbed.<name>...,predicted.<name>...
// Files appear only when complete (lib/output/atomic_file.hpp).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/sensitivity/trajectory_sensitivity.hpp"

namespace impactbench::sensitivity {

void write_sensitivity_csv(std::ostream& out, const TrajectorySensitivity& sensitivity,
                           const EndPointSensitivity& end_point);
/// Throws std::runtime_error naming the file if it cannot be written.
void write_sensitivity_csv_file(const std::filesystem::path& path,
                                const TrajectorySensitivity& sensitivity,
                                const EndPointSensitivity& end_point);

struct PredictionSeries {
  std::vector<std::string> state_names;  ///< n names, e.g. "box.y"
  std::vector<double> times;
  std::vector<Eigen::VectorXd> nominal, perturbed, predicted;  ///< one state per time
};
/// Throws std::invalid_argument for inconsistent sizes, std::runtime_error for I/O failures.
void write_prediction_csv(std::ostream& out, const PredictionSeries& series);
void write_prediction_csv_file(const std::filesystem::path& path, const PredictionSeries& series);

/// The gains file and, when both are given, the prediction file, committed together: a failure
/// of either (a full device) leaves neither.
void write_sensitivity_outputs(const std::filesystem::path& gains_path,
                               const TrajectorySensitivity& sensitivity,
                               const EndPointSensitivity& end_point,
                               const std::filesystem::path* prediction_path = nullptr,
                               const PredictionSeries* series = nullptr);

}  // namespace impactbench::sensitivity
