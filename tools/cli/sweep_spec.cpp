#include "tools/cli/sweep_spec.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lib/engines/settings/settings_set.hpp"
#include "lib/resources/resource_paths.hpp"
#include "lib/scenario/document.hpp"
#include "lib/scenario/scenario_error.hpp"
#include "lib/validation/toss_selection.hpp"
#include "tools/cli/document_values.hpp"

namespace impactbench::cli {

std::filesystem::path SpecValidate::folder() const {
  return data.empty() ? resources::cube_toss_directory() : data;
}

namespace {

using scenario::DocumentNode;
using scenario::ScenarioError;

class SpecReader {
 public:
  explicit SpecReader(SweepSpec& spec) : spec_(spec) {}

  [[noreturn]] void fail(int line, const std::string& field, const std::string& what) const {
    throw ScenarioError(spec_.path.string(), line, field, what);
  }

  std::string scalar_text(const DocumentNode& node, const std::string& field) const {
    return cli::scalar_text(node, spec_.path, field);
  }

  /// A list of values (a single value counts as a list of one); an empty list is refused.
  std::vector<SpecValue> values(const DocumentNode& node, const std::string& field,
                                bool numbers_only, bool text_only) const {
    std::vector<const DocumentNode*> items;
    if (node.kind == DocumentNode::Kind::kArray)
      for (const DocumentNode& item : node.items) items.push_back(&item);
    else
      items.push_back(&node);
    if (items.empty()) fail(node.line, field, "is an empty grid (give at least one value)");
    std::vector<SpecValue> out;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const DocumentNode& item = *items[i];
      const std::string item_field = field + "[" + std::to_string(i) + "]";
      if (numbers_only && item.kind != DocumentNode::Kind::kNumber)
        fail(item.line, item_field, "needs a number, not a " + scenario::kind_name(item.kind));
      if (text_only && item.kind != DocumentNode::Kind::kString)
        fail(item.line, item_field, "needs a name, not a " + scenario::kind_name(item.kind));
      if (numbers_only && !(item.number > 0))
        fail(item.line, item_field, "needs a positive number");
      for (const SpecValue& seen : out)
        if (seen.text == scalar_text(item, item_field))
          fail(item.line, item_field, "'" + seen.text + "' is given twice");
      out.push_back({scalar_text(item, item_field), item.line > 0 ? item.line : node.line});
    }
    return out;
  }

  double positive(const DocumentNode& node, const std::string& field) const {
    if (node.kind != DocumentNode::Kind::kNumber || !std::isfinite(node.number) ||
        !(node.number > 0))
      fail(node.line, field, "needs a positive number");
    return node.number;
  }

  std::size_t count(const DocumentNode& node, const std::string& field) const {
    const double n = positive(node, field);
    if (n != std::floor(n) || n > 1e6) fail(node.line, field, "needs a whole number up to 1e6");
    return static_cast<std::size_t>(n);
  }

  std::string text(const DocumentNode& node, const std::string& field) const {
    if (node.kind != DocumentNode::Kind::kString || node.text.empty())
      fail(node.line, field, "needs a non-empty text");
    return node.text;
  }

  const DocumentNode& table(const DocumentNode& node, const std::string& field) const {
    if (node.kind != DocumentNode::Kind::kTable) fail(node.line, field, "needs a table");
    return node;
  }

  void read_grid(const DocumentNode& grid) {
    for (const auto& [key, node] : grid.entries) {
      const std::string field = "grid." + key;
      if (key == "dt" || key == "tolerance")
        (key == "dt" ? spec_.dt : spec_.tolerance) =
            SpecAxis{field, "", node.line, values(node, field, true, false)};
      else if (key == "solver")
        spec_.solver = SpecAxis{field, "", node.line, values(node, field, false, true)};
      else if (key == "settings")
        spec_.settings_set = settings_sets(node, field);
      else if (key == "set" || key == "option")
        for (const auto& [name, axis] : table(node, field).entries) {
          const std::string axis_field = field + "." + name;
          (key == "set" ? spec_.sets : spec_.options)
              .push_back({axis_field, name, axis.line, values(axis, axis_field, false, false)});
        }
      else
        fail(node.line, field,
             "is not a key of [grid] (dt, tolerance, solver, settings, set, option)");
    }
  }

  /// grid.settings: names of settings sets (`--settings` of compare), each checked here.
  SpecAxis settings_sets(const DocumentNode& node, const std::string& field) const {
    SpecAxis axis{field, "", node.line, values(node, field, false, true)};
    for (std::size_t i = 0; i < axis.values.size(); ++i) try {
        engines::parse_settings_set(axis.values[i].text);
      } catch (const std::invalid_argument& error) {
        fail(axis.values[i].line, field + "[" + std::to_string(i) + "]", error.what());
      }
    return axis;
  }

  void read_validate(const DocumentNode& node) {
    SpecValidate validate;
    validate.line = node.line;
    for (const auto& [key, value] : node.entries) {
      const std::string field = "validate." + key;
      if (key == "tosses") {
        validate.tosses = text(value, field);
        try {
          validation::parse_toss_selection(validate.tosses);
        } catch (const std::invalid_argument& error) {
          fail(value.line, field, error.what());
        }
      } else if (key == "initial_state") {
        validate.initial_state = text(value, field);
        if (validate.initial_state != "sample" && validate.initial_state != "fit")
          fail(value.line, field, "needs sample or fit, not '" + validate.initial_state + "'");
      } else if (key == "data") {
        validate.data = text(value, field);
        if (validate.data.is_relative()) validate.data = spec_.path.parent_path() / validate.data;
      } else {
        fail(value.line, field, "is not a key of [validate] (tosses, initial_state, data)");
      }
    }
    // The tosses must be there before any point runs, not found missing by every point.
    const std::filesystem::path data = validate.folder();
    std::error_code error;
    if (!std::filesystem::is_directory(data, error))
      fail(node.line, "validate.data", data.string() + " is not a directory");
    if (validation::select_toss_files(data, validation::parse_toss_selection(validate.tosses))
            .empty())
      fail(node.line, "validate.tosses",
           "selects no toss file (*.csv) of " + data.string() + " ('" + validate.tosses + "')");
    spec_.validate = validate;
  }

  void read_slurm(const DocumentNode& slurm) {
    for (const auto& [key, node] : slurm.entries) {
      const std::string field = "slurm." + key;
      if (key == "shards")
        spec_.slurm_shards = count(node, field);
      else if (key == "concurrency")
        spec_.slurm_concurrency = count(node, field);
      else if (key == "time")
        spec_.slurm_time = text(node, field);
      else if (key == "mem")
        spec_.slurm_mem = text(node, field);
      else if (key == "partition")
        spec_.slurm_partition = text(node, field);
      else
        fail(node.line, field,
             "is not a key of [slurm] (shards, concurrency, time, mem, partition)");
    }
  }

  void read(const DocumentNode& root) {
    for (const auto& [key, node] : root.entries) {
      if (key == "scenarios")
        spec_.scenarios = values(node, key, false, true);
      else if (key == "engines")
        spec_.engines = values(node, key, false, true);
      else if (key == "duration")
        spec_.duration = positive(node, key);
      else if (key == "time_limit")
        spec_.time_limit = positive(node, key);
      else if (key == "grid") {
        spec_.grid_line = node.line;
        read_grid(table(node, key));
      } else if (key == "slurm")
        read_slurm(table(node, key));
      else if (key == "validate")
        read_validate(table(node, key));
      else
        fail(node.line, key,
             "is not a key of a sweep file (scenarios, engines, duration, time_limit, grid, "
             "validate, slurm)");
    }
    if (spec_.scenarios.empty()) fail(0, "scenarios", "is missing (the scenarios to sweep)");
    if (spec_.engines.empty()) fail(0, "engines", "is missing (the engines to sweep)");
  }

 private:
  SweepSpec& spec_;
};

}  // namespace

SweepSpec read_sweep_spec(const std::filesystem::path& path) {
  SweepSpec spec;
  spec.path = path;
  const DocumentNode root = scenario::parse_document(path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  spec.text = text.str();
  SpecReader(spec).read(root);
  return spec;
}

}  // namespace impactbench::cli
