#pragma once
// Named expressions that may refer to each other ([derived] and [analytic] in a scenario file):
// evaluating one first evaluates, depth first, the named expressions it reads, writing each
// result into its variable slot. Cycles are detected once, when the file is loaded.
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lib/scenario/expression.hpp"

namespace impactbench::scenario {

class NamedExpressions {
 public:
  /// `variables` holds a slot for every name added here (and whatever else they read); it must
  /// outlive this object.
  explicit NamedExpressions(VariableTable& variables) : variables_(&variables) {}

  void add(const std::string& name, Expression expression);
  bool contains(const std::string& name) const { return index_of(name) >= 0; }
  const std::vector<std::string>& names() const { return names_; }

  /// A dependency cycle as "a -> b -> a", or an empty vector when there is none.
  std::vector<std::string> find_cycle() const;

  /// Whether `name` reads `variable`, directly or through the named expressions it reads.
  /// Requires an acyclic set.
  bool reads(const std::string& name, const std::string& variable) const;

  /// Value of `name`; its dependencies are evaluated first. Requires an acyclic set.
  double evaluate(const std::string& name) const;

  /// Every value, in the order the names were added, each expression evaluated once (a chain
  /// of n names costs n evaluations, not n²). Requires an acyclic set.
  std::vector<std::pair<std::string, double>> evaluate_all() const;

 private:
  int index_of(const std::string& name) const;
  double evaluate_index(int index, std::vector<bool>& evaluated) const;
  bool visit_for_cycle(int index, std::vector<int>& state, std::vector<int>& stack,
                       std::vector<std::string>& cycle) const;

  VariableTable* variables_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, int> index_;  // name → position in names_
  std::vector<Expression> expressions_;
};

}  // namespace impactbench::scenario
