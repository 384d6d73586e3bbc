#pragma once
// Shared helpers of the section readers of scenario_loader.cpp and body_section.cpp: typed
// access to a table of the document with errors that carry path, line and field name, and
// compilation of numeric fields (a number or an expression string) against the parameters.
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "lib/scenario/document.hpp"
#include "lib/scenario/expression.hpp"
#include "lib/scenario/scenario.hpp"

namespace impactbench::scenario {

/// What every section reader needs: the file path (for messages), the dimension and the
/// values that numeric fields may refer to (parameters after overrides, then [derived]).
struct LoadContext {
  std::string path;
  const EngineCatalog* engines = nullptr;  ///< what `engines` and [settings.ENGINE] may name
  Dimension dimension = Dimension::kPlanar;
  std::vector<std::pair<std::string, double>> named_values;
  /// The parameters the user overrode (--set), and the names each [derived] entry reads, so
  /// that a formula that fails for the user's values can say which of them made it fail.
  std::vector<std::pair<std::string, double>> overrides;
  std::map<std::string, std::vector<std::string>> derived_reads;

  /// " for --set a=1, --set b=2" naming the overridden parameters `expression` reads (also
  /// through [derived] names); "" when it reads none.
  std::string blame(const Expression& expression) const;

  int vector_size() const { return dimension == Dimension::kPlanar ? 2 : 3; }
  /// A fresh table with the named values plus `extra` slots (e.g. "i", "t", "k") set to 0.
  VariableTable make_variables(std::initializer_list<std::string_view> extra = {}) const;

  [[noreturn]] void fail(int line, const std::string& field, const std::string& problem) const;

  /// A number node becomes a constant, a string node is compiled; anything else is an error.
  Expression compile(const DocumentNode& node, const std::string& field,
                     VariableTable& variables) const;
  /// Evaluates and rejects NaN/Inf (`where` is appended to the message, e.g. " at i = 3").
  double finite_value(const Expression& expression, const DocumentNode& node,
                      const std::string& field, const std::string& where = "") const;
};

/// One table of the document, read field by field.
class TableReader {
 public:
  TableReader(const LoadContext& context, const DocumentNode& table, std::string prefix);

  const DocumentNode* optional(const std::string& key) const { return table_->find(key); }
  const DocumentNode& required(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::string optional_string(const std::string& key, const std::string& fallback) const;
  bool optional_boolean(const std::string& key, bool fallback) const;
  /// Rejects keys outside `allowed` (catches typos such as "restitutoin").
  void allow_only(std::initializer_list<std::string_view> allowed) const;

  std::string field(const std::string& key) const { return prefix_ + key; }
  int line() const { return table_->line; }
  const DocumentNode& node() const { return *table_; }
  const LoadContext& context() const { return *context_; }

 private:
  const LoadContext* context_;
  const DocumentNode* table_;
  std::string prefix_;
};

/// Requires `node` to be of `kind`.
void expect_kind(const LoadContext& context, const DocumentNode& node, DocumentNode::Kind kind,
                 const std::string& field);

/// A fixed-size vector field of numbers/expressions, e.g. position = [0, "height"].
std::vector<Expression> compile_vector(const LoadContext& context, const DocumentNode& node,
                                       const std::string& field, int size,
                                       VariableTable& variables);
/// Evaluates each component (finite) into a 3-vector, unused components left 0.
Eigen::Vector3d evaluate_vector(const LoadContext& context, const std::vector<Expression>& parts,
                                const DocumentNode& node, const std::string& field,
                                const std::string& where = "");

/// Reads the optional [settings.ENGINE] tables, each value checked against that engine's
/// settings by the catalog (engine_settings_section.cpp); needs the scenario's engines and
/// duration.
std::map<std::string, std::vector<std::pair<std::string, std::string>>> read_engine_settings(
    const LoadContext& context, const TableReader& root, const Scenario& scenario);

/// Reads the [[bodies]] array into BodySpecs (body_section.cpp).
std::vector<model::BodySpec> read_bodies(const LoadContext& context, const DocumentNode& bodies);

}  // namespace impactbench::scenario
