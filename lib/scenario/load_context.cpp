#include "lib/scenario/load_context.hpp"

#include <cmath>
#include <set>

#include "lib/output/message_text.hpp"

namespace impactbench::scenario {

std::string LoadContext::blame(const Expression& expression) const {
  std::set<std::string> seen;
  std::vector<std::string> pending = expression.used_variables();
  while (!pending.empty()) {
    const std::string name = pending.back();
    pending.pop_back();
    if (!seen.insert(name).second) continue;
    if (const auto it = derived_reads.find(name); it != derived_reads.end())
      pending.insert(pending.end(), it->second.begin(), it->second.end());
  }
  std::string out;
  for (const auto& [name, value] : overrides)
    if (seen.count(name))
      out += (out.empty() ? " for --set " : ", --set ") + name + "=" + output::number_text(value);
  return out;
}

VariableTable LoadContext::make_variables(std::initializer_list<std::string_view> extra) const {
  VariableTable variables;
  for (const auto& [name, value] : named_values) variables.define(name, value);
  for (const auto name : extra) variables.define(std::string(name), 0.0);
  return variables;
}

void LoadContext::fail(int line, const std::string& field, const std::string& problem) const {
  throw ScenarioError(path, line, field, problem);
}

Expression LoadContext::compile(const DocumentNode& node, const std::string& field,
                                VariableTable& variables) const {
  if (node.kind == DocumentNode::Kind::kNumber) return Expression::constant(node.number);
  if (node.kind != DocumentNode::Kind::kString)
    fail(node.line, field,
         "expected a number or an expression string, got " + kind_name(node.kind));
  try {
    return Expression(node.text, variables);
  } catch (const ExpressionError& error) {
    fail(node.line, field, error.what());
  }
}

double LoadContext::finite_value(const Expression& expression, const DocumentNode& node,
                                 const std::string& field, const std::string& where) const {
  double value = 0.0;
  try {
    value = expression.evaluate();
  } catch (const ExpressionError& error) {
    fail(node.line, field, error.what() + where + blame(expression));
  }
  if (!std::isfinite(value))
    fail(node.line, field,
         "'" + expression.source() + "' is not finite (" + output::number_text(value) + ")" +
             where + blame(expression));
  return value;
}

TableReader::TableReader(const LoadContext& context, const DocumentNode& table, std::string prefix)
    : context_(&context), table_(&table), prefix_(std::move(prefix)) {
  if (table.kind != DocumentNode::Kind::kTable) {
    std::string name = prefix_;
    if (!name.empty() && name.back() == '.') name.pop_back();
    context.fail(table.line, name, "expected a table, got " + kind_name(table.kind));
  }
}

const DocumentNode& TableReader::required(const std::string& key) const {
  const DocumentNode* node = optional(key);
  if (!node) context_->fail(table_->line, field(key), "missing required field");
  return *node;
}

std::string TableReader::string(const std::string& key) const {
  const DocumentNode& node = required(key);
  expect_kind(*context_, node, DocumentNode::Kind::kString, field(key));
  return node.text;
}

std::string TableReader::optional_string(const std::string& key,
                                         const std::string& fallback) const {
  return optional(key) ? string(key) : fallback;
}

bool TableReader::optional_boolean(const std::string& key, bool fallback) const {
  const DocumentNode* node = optional(key);
  if (!node) return fallback;
  expect_kind(*context_, *node, DocumentNode::Kind::kBoolean, field(key));
  return node->boolean;
}

void TableReader::allow_only(std::initializer_list<std::string_view> allowed) const {
  for (const auto& [key, value] : table_->entries) {
    bool known = false;
    for (const auto name : allowed) known = known || key == name;
    if (known) continue;
    std::string list;
    for (const auto name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
    context_->fail(value.line, field(key), "unknown field (allowed: " + list + ")");
  }
}

void expect_kind(const LoadContext& context, const DocumentNode& node, DocumentNode::Kind kind,
                 const std::string& field) {
  if (node.kind != kind)
    context.fail(node.line, field,
                 "expected a " + kind_name(kind) + ", got " + kind_name(node.kind));
}

std::vector<Expression> compile_vector(const LoadContext& context, const DocumentNode& node,
                                       const std::string& field, int size,
                                       VariableTable& variables) {
  expect_kind(context, node, DocumentNode::Kind::kArray, field);
  if (static_cast<int>(node.items.size()) != size)
    context.fail(node.line, field,
                 "expected " + std::to_string(size) + " components (" +
                     to_string(context.dimension) + "), got " + std::to_string(node.items.size()));
  std::vector<Expression> parts;
  for (std::size_t i = 0; i < node.items.size(); ++i)
    parts.push_back(
        context.compile(node.items[i], field + "[" + std::to_string(i) + "]", variables));
  return parts;
}

Eigen::Vector3d evaluate_vector(const LoadContext& context, const std::vector<Expression>& parts,
                                const DocumentNode& node, const std::string& field,
                                const std::string& where) {
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < parts.size(); ++i)
    value[static_cast<Eigen::Index>(i)] =
        context.finite_value(parts[i], node.items[i], field + "[" + std::to_string(i) + "]", where);
  return value;
}

}  // namespace impactbench::scenario
