// `impactbench describe SCENARIO [--set k=v]... [--settings default|expert]`: what a scenario is,
// its parameters with values, defaults and units, the engines that can run it, run defaults, each
// engine's settings in force with their source, and the analytic quantities (evaluated, k = 0 for
// indexed ones), as "key: value" lines for people and greps.
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "lib/output/number_text.hpp"
#include "lib/scenario/scenario.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/overrides.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/engines/registry/run_settings.hpp"
#include "tools/engines/registry/scenario_loading.hpp"

namespace impactbench::cli {

namespace {

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string body_summary(const scenario::Scenario& s) {
  if (s.bodies.size() <= 6) {
    std::vector<std::string> names;
    for (const auto& body : s.bodies) names.push_back(body.name);
    return join(names);
  }
  return std::to_string(s.bodies.size()) + " (" + s.bodies.front().name + " ... " +
         s.bodies.back().name + ")";
}

std::size_t widest(const auto& items) {
  std::size_t width = 0;
  for (const auto& item : items) width = std::max(width, item.name.size());
  return width;
}

class DescribeCommand : public Command {
 public:
  explicit DescribeCommand(CLI::App* app) : Command(app) {
    app->add_option("scenario", name_, "Scenario name (see `impactbench list`)")->required();
    app->add_option("--set", sets_, "Override a parameter: name=value (repeatable)");
    add_settings_set_option(app, settings_set_);
  }

  int run() override {
    const auto s = scenario::load_scenario_by_name(name_, parse_overrides(sets_));
    auto& out = std::cout;
    out << "name: " << s.name << '\n'
        << "description: " << s.description << '\n'
        << "file: " << s.path.string() << '\n'
        << "dimension: " << to_string(s.dimension) << '\n'
        << "system: " << to_string(s.system) << '\n'
        << "engines: " << join(s.engines) << '\n'
        << "duration: " << output::number_text(s.duration) << " s\n"
        << "dt: " << output::number_text(s.dt) << " s\n"
        << "tolerance: " << output::number_text(s.tolerance) << '\n'
        << "bodies: " << body_summary(s) << '\n';
    std::vector<std::string> planes;
    for (const auto& plane : s.planes) planes.push_back(plane.name);
    out << "planes: " << (planes.empty() ? "none" : join(planes)) << '\n';
    std::vector<std::string> inputs;
    for (const auto& input : s.inputs) inputs.push_back("force on " + input.body);
    out << "inputs: " << (inputs.empty() ? "none" : join(inputs)) << '\n';

    out << "parameters:\n";
    const auto width = static_cast<int>(widest(s.parameters));
    for (const auto& p : s.parameters) {
      out << "  " << std::left << std::setw(width) << p.name << " = "
          << output::number_text(p.value) << ' ' << p.unit;
      if (p.value != p.default_value)
        out << " (default " << output::number_text(p.default_value) << ')';
      out << "  " << p.description << '\n';
    }
    // Each engine's settings as `run` would use them: defaults, the set asked for, then the
    // scenario's.
    engines::SettingsRequest request;
    request.set = settings_set_of(settings_set_);
    for (const std::string& engine : s.engines) {
      out << "settings of " << engine << ":\n";
      const engines::RunOptions options = engines::resolve_run_options(engine, s, request);
      for (const auto& setting : options.settings)
        out << "  " << setting.key << " = " << setting.value << " ("
            << engines::to_string(setting.source) << ")\n";
    }
    out << "analytic:\n";
    const auto analytic_width = static_cast<int>(widest(s.analytic_quantities));
    for (const auto& q : s.analytic_quantities) {
      const std::string label = q.name + (q.indexed ? "(k)" : "");
      out << "  " << std::left << std::setw(analytic_width + 3) << label << " = "
          << output::number_text(s.analytic(q.name, 0)) << ' ' << q.unit
          << (q.indexed ? " at k = 0" : "") << "  " << q.description << "  [" << q.expression
          << "]\n";
    }
    return 0;
  }

 private:
  std::string name_;
  std::vector<std::string> sets_;
  std::string settings_set_;
};

}  // namespace

std::unique_ptr<Command> add_describe_command(CLI::App& app) {
  return std::make_unique<DescribeCommand>(app.add_subcommand(
      "describe", "Describe a scenario: parameters, defaults, engines, analytic quantities"));
}

}  // namespace impactbench::cli
