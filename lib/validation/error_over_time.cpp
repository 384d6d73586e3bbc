#include "lib/validation/error_over_time.hpp"

#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>

namespace impactbench::validation {

std::vector<ErrorBin> error_over_time(const std::vector<std::vector<SampleError>>& tosses,
                                      double width) {
  if (!(width > 0.0) || !std::isfinite(width))
    throw std::invalid_argument("error_over_time: the bin width must be positive and finite");
  // bin → per toss, its means in that bin
  std::map<long, std::pair<std::vector<double>, std::vector<double>>> bins;
  for (const auto& errors : tosses) {
    std::map<long, std::pair<SampleError, int>> sums;  // bin → summed errors, sample count
    for (const SampleError& e : errors) {
      auto& [sum, count] = sums[static_cast<long>(std::floor(e.time / width))];
      sum.position += e.position;
      sum.rotation += e.rotation;
      ++count;
    }
    for (const auto& [bin, sum] : sums) {
      bins[bin].first.push_back(sum.first.position / sum.second);
      bins[bin].second.push_back(sum.first.rotation / sum.second);
    }
  }
  std::vector<ErrorBin> out;
  for (const auto& [bin, values] : bins)
    out.push_back(
        {static_cast<double>(bin) * width, statistics(values.first), statistics(values.second)});
  return out;
}

}  // namespace impactbench::validation
