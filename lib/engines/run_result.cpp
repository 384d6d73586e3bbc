#include "lib/engines/run_result.hpp"

#include <cmath>
#include <stdexcept>

#include "lib/output/message_text.hpp"

namespace impactbench::engines {

namespace {

/// "ball.y = nan" for the first non-finite entry of `values`, "" when all are finite.
std::string first_non_finite(const Eigen::VectorXd& values, const std::vector<std::string>& names,
                             const char* fallback) {
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (!std::isfinite(values(i))) {
      const auto index = static_cast<std::size_t>(i);
      const std::string name =
          index < names.size() ? names[index] : fallback + std::to_string(i) + "]";
      return name + " = " + output::number_text(values(i));
    }
  return "";
}

}  // namespace

void RunResult::add_sample(double t, Eigen::VectorXd q, Eigen::VectorXd v, double energy) {
  std::string bad = first_non_finite(q, trajectory.position_names, "q[");
  if (bad.empty()) bad = first_non_finite(v, trajectory.velocity_names, "v[");
  if (bad.empty() && std::isinf(energy)) bad = "energy = " + output::number_text(energy);
  if (!bad.empty())
    throw std::runtime_error((engine.empty() ? std::string("run") : engine) +
                             ": the state became non-finite at t = " + output::number_text(t) +
                             " (" + bad +
                             "); the values are outside what the engine can "
                             "compute with");
  trajectory.samples.push_back({t, std::move(q), std::move(v), energy});
}

}  // namespace impactbench::engines
