#include "lib/scenario/named_expressions.hpp"

#include <algorithm>

namespace impactbench::scenario {

void NamedExpressions::add(const std::string& name, Expression expression) {
  index_.emplace(name, static_cast<int>(names_.size()));
  names_.push_back(name);
  expressions_.push_back(std::move(expression));
}

int NamedExpressions::index_of(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? -1 : it->second;
}

double NamedExpressions::evaluate(const std::string& name) const {
  const int index = index_of(name);
  if (index < 0) throw std::out_of_range("no expression named '" + name + "'");
  std::vector<bool> evaluated(names_.size(), false);
  return evaluate_index(index, evaluated);
}

std::vector<std::pair<std::string, double>> NamedExpressions::evaluate_all() const {
  std::vector<bool> evaluated(names_.size(), false);
  std::vector<std::pair<std::string, double>> values;
  values.reserve(names_.size());
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (!evaluated[i]) evaluate_index(static_cast<int>(i), evaluated);
    values.emplace_back(names_[i], variables_->at(names_[i]));
  }
  return values;
}

double NamedExpressions::evaluate_index(int index, std::vector<bool>& evaluated) const {
  const Expression& expression = expressions_[static_cast<std::size_t>(index)];
  // Each name is evaluated once per call: a chain where every name reads the two before it
  // would otherwise take exponential time.
  for (const auto& used : expression.used_variables()) {
    const int dependency = index_of(used);
    if (dependency >= 0 && !evaluated[static_cast<std::size_t>(dependency)])
      evaluate_index(dependency, evaluated);
  }
  evaluated[static_cast<std::size_t>(index)] = true;
  const double value = expression.evaluate();
  variables_->at(names_[static_cast<std::size_t>(index)]) = value;
  return value;
}

bool NamedExpressions::reads(const std::string& name, const std::string& variable) const {
  // Breadth over the names reachable from `name`, each visited once (a chain of names reading
  // each other would otherwise be followed along every path).
  std::vector<bool> visited(names_.size(), false);
  std::vector<int> pending;
  if (const int start = index_of(name); start >= 0) pending.push_back(start);
  while (!pending.empty()) {
    const int index = pending.back();
    pending.pop_back();
    if (visited[static_cast<std::size_t>(index)]) continue;
    visited[static_cast<std::size_t>(index)] = true;
    for (const auto& used : expressions_[static_cast<std::size_t>(index)].used_variables()) {
      if (used == variable) return true;
      if (const int next = index_of(used); next >= 0) pending.push_back(next);
    }
  }
  return false;
}

std::vector<std::string> NamedExpressions::find_cycle() const {
  // Depth-first search with the usual three colours: 0 unvisited, 1 on the stack, 2 done.
  std::vector<int> state(names_.size(), 0);
  std::vector<int> stack;
  std::vector<std::string> cycle;
  for (int i = 0; i < static_cast<int>(names_.size()); ++i)
    if (state[static_cast<std::size_t>(i)] == 0 && visit_for_cycle(i, state, stack, cycle))
      return cycle;
  return {};
}

bool NamedExpressions::visit_for_cycle(int index, std::vector<int>& state, std::vector<int>& stack,
                                       std::vector<std::string>& cycle) const {
  state[static_cast<std::size_t>(index)] = 1;
  stack.push_back(index);
  for (const auto& used : expressions_[static_cast<std::size_t>(index)].used_variables()) {
    const int next = index_of(used);
    if (next < 0) continue;
    if (state[static_cast<std::size_t>(next)] == 1) {
      const auto start = std::find(stack.begin(), stack.end(), next);
      for (auto it = start; it != stack.end(); ++it)
        cycle.push_back(names_[static_cast<std::size_t>(*it)]);
      cycle.push_back(names_[static_cast<std::size_t>(next)]);
      return true;
    }
    if (state[static_cast<std::size_t>(next)] == 0 && visit_for_cycle(next, state, stack, cycle))
      return true;
  }
  stack.pop_back();
  state[static_cast<std::size_t>(index)] = 2;
  return false;
}

}  // namespace impactbench::scenario
