#pragma once
// The pieces an engine's settings are described with: one field per key (how its text is read,
// what it accepts, how its value in force is shown), the parsers behind them and the error a
// refused value or key raises. Every engine's schema is a list of these fields, so that every
// engine reads, refuses and reports its settings alike.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/output/number_text.hpp"

namespace impactbench::engines {

/// Where a setting in force came from, lowest precedence first.
enum class SettingSource {
  kDefault,      ///< the engine's default
  kExpert,       ///< the engine's expert set (--settings expert), from its own documentation
  kScenario,     ///< the scenario file (its dt/tolerance or its [settings.ENGINE] table)
  kCommandLine,  ///< --dt, --tol, --solver, --duration or --option
  kBuiltIn,      ///< compiled into the engine, not a setting (e.g. Box2D's linear slop)
  /// chosen by compare for the run that serves as the reference trajectory, so that it is
  /// sampled as finely as the compared runs (the event engine's output_interval)
  kReferenceSampling,
};
std::string to_string(SettingSource source);  ///< "default", "expert", "scenario", ...

/// One setting as given or as in force: its value as text (numbers as output::number_text).
struct SettingValue {
  std::string key;
  std::string value;
  SettingSource source = SettingSource::kDefault;
};
using SettingList = std::vector<SettingValue>;

/// A refused setting: what() is "<engine>: setting '<key>' <detail>"; detail() alone serves
/// messages that say where the value came from themselves (path:line: field: detail).
class SettingError : public std::invalid_argument {
 public:
  SettingError(const std::string& engine, const std::string& key, const std::string& detail)
      : std::invalid_argument(engine + ": setting '" + key + "' " + detail), detail_(detail) {}
  const std::string& detail() const { return detail_; }

 private:
  std::string detail_;
};

/// The parsers throw std::invalid_argument with a detail such as "must be in [0.5, 1], got '2'".
struct NumberRange {
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;   ///< low itself excluded
  bool high_open = false;  ///< high itself excluded (an infinite high is always open)
  bool contains(double x) const;
  std::string text() const;  ///< "in [0.5, 1]", "> 0", ">= 0", "in (0, 1]"
};
double parse_number(const std::string& text, const NumberRange& range);
/// A whole number in [low, high]; out of range says so before "must be a whole number".
int parse_whole(const std::string& text, int low, int high);
bool parse_switch(const std::string& text);  ///< 0/1 or true/false only
std::string switch_text(bool value);         ///< "true" | "false"
/// `text` when it is one of `names`, else "must be one of a, b, c, got 'x'".
std::string parse_name(const std::string& text, const std::vector<std::string>& names);
std::string join_names(const std::vector<std::string>& names, const std::string& last = "or");

/// One key of an engine's settings, for an options struct O.
template <typename O>
struct SettingField {
  std::string key;
  std::string accepts;  ///< what it accepts, e.g. "a number in [0.5, 1]" (messages, docs)
  std::function<void(O&, const std::string&)> parse;  ///< throws std::invalid_argument
  std::function<std::string(const O&)> show;          ///< the value in force, read back by parse
};

template <typename O>
SettingField<O> number_field(std::string key, double O::*member, NumberRange range) {
  return {std::move(key), "a number " + range.text(),
          [member, range](O& o, const std::string& v) { o.*member = parse_number(v, range); },
          [member](const O& o) { return output::number_text(o.*member); }};
}

/// A number, or the word `unset_word` leaving it unset (the engine then derives it, e.g. the
/// activation horizon γ = θ); shown as that word while unset.
template <typename O>
SettingField<O> optional_number_field(std::string key, std::optional<double> O::*member,
                                      NumberRange range, std::string unset_word) {
  return {std::move(key), "a number " + range.text() + " or '" + unset_word + "'",
          [member, range, unset_word](O& o, const std::string& v) {
            if (v == unset_word)
              o.*member = std::nullopt;
            else
              o.*member = parse_number(v, range);
          },
          [member, unset_word](const O& o) {
            return o.*member ? output::number_text(*(o.*member)) : unset_word;
          }};
}

template <typename O>
SettingField<O> whole_field(std::string key, int O::*member, int low, int high) {
  return {
      std::move(key),
      "a whole number in [" + std::to_string(low) + ", " + std::to_string(high) + "]",
      [member, low, high](O& o, const std::string& v) { o.*member = parse_whole(v, low, high); },
      [member](const O& o) { return std::to_string(o.*member); }};
}

template <typename O>
SettingField<O> switch_field(std::string key, bool O::*member) {
  return {std::move(key), "0/1 or true/false",
          [member](O& o, const std::string& v) { o.*member = parse_switch(v); },
          [member](const O& o) { return switch_text(o.*member); }};
}

/// A name from a list known at run time (e.g. a solver registry).
template <typename O>
SettingField<O> name_field(std::string key, std::string O::*member,
                           std::vector<std::string> names) {
  return {std::move(key), "one of " + join_names(names),
          [member, names](O& o, const std::string& v) { o.*member = parse_name(v, names); },
          [member](const O& o) { return o.*member; }};
}

/// A name standing for a value of an enumeration.
template <typename O, typename E>
SettingField<O> choice_field(std::string key, E O::*member,
                             std::vector<std::pair<std::string, E>> choices) {
  std::vector<std::string> names;
  for (const auto& [name, value] : choices) names.push_back(name);
  return {std::move(key), "one of " + join_names(names),
          [member, choices, names](O& o, const std::string& v) {
            const std::string name = parse_name(v, names);
            for (const auto& [n, value] : choices)
              if (n == name) o.*member = value;
          },
          [member, choices](const O& o) {
            for (const auto& [name, value] : choices)
              if (o.*member == value) return name;
            return std::string("?");
          }};
}

}  // namespace impactbench::engines
