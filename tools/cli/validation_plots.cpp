#include "tools/cli/validation_plots.hpp"

#include <stdexcept>

#include "tools/compare/run_process.hpp"

namespace impactbench::cli {

const std::vector<std::string>& validation_plot_names() {
  static const std::vector<std::string> names = {"error_over_time.png", "error_distribution.png",
                                                 "toss_trajectory.png"};
  return names;
}

void plot_validation(const std::filesystem::path& python, const std::filesystem::path& tools_dir,
                     const std::filesystem::path& out) {
  std::vector<std::filesystem::path> pngs;
  for (const auto& name : validation_plot_names()) pngs.push_back(out / name);
  if (compare::run_process(
          {python.string(), (tools_dir / "plot_validation.py").string(), out.string()}, pngs) != 0)
    throw std::runtime_error("validate: plotting failed (" + python.string() +
                             " tools/plot_validation.py); is python3-matplotlib installed?");
}

}  // namespace impactbench::cli
