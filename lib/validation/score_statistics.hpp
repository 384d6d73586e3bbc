#pragma once
// Mean, median and 90th percentile of a metric over tosses (percentiles interpolate linearly
// between order statistics: position p (n − 1) in the sorted values, numpy's default).
#include <vector>

namespace impactbench::validation {

struct Statistics {
  int count = 0;
  double mean = 0.0;
  double median = 0.0;
  double p90 = 0.0;
};

/// Throws std::invalid_argument on an empty list.
double percentile(std::vector<double> values, double p);
/// count 0 and NaN statistics for an empty list.
Statistics statistics(const std::vector<double>& values);

}  // namespace impactbench::validation
