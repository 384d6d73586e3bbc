#pragma once
// Errors against time since the start of the runs, over many tosses: the statistics behind
// validate's "error against time" plot. Time is cut into bins of a fixed width; a toss counts
// once per bin (the mean of its samples there), so a toss sampled faster does not weigh more.
#include <vector>

#include "lib/validation/score_statistics.hpp"
#include "lib/validation/toss_score.hpp"

namespace impactbench::validation {

struct ErrorBin {
  double start = 0.0;   ///< [s] since the run's first sample; the bin is [start, start + width)
  Statistics position;  ///< over the tosses with a sample in the bin [sides]
  Statistics rotation;  ///< [rad]
};

/// The bins from 0 to the latest sample of any toss, each with at least one toss (bins no toss
/// reaches are left out). Throws std::invalid_argument unless width is positive and finite.
std::vector<ErrorBin> error_over_time(const std::vector<std::vector<SampleError>>& tosses,
                                      double width);

}  // namespace impactbench::validation
