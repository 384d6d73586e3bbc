#pragma once
// Reading one toss file: a header naming at least t, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy,
// wz (any order, other columns ignored), then one row per sample. Refused, as TossDataError
// with "path:line: what": a file that is not CSV text (NUL bytes, a row with another number of
// fields than the header, a field that is not a number), a missing column, a NaN or infinite
// value, a quaternion whose norm differs from 1 by more than kQuaternionTolerance, a time that
// does not increase, fewer than two samples.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "lib/validation/toss.hpp"

namespace impactbench::validation {

/// |‖q‖ − 1| allowed; the shipped data hold unit quaternions to 5e-16.
inline constexpr double kQuaternionTolerance = 1e-6;

class TossDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads `path`; the toss's name is the file's stem. Quaternions are normalised after the check.
Toss read_toss(const std::filesystem::path& path);

}  // namespace impactbench::validation
