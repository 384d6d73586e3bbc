#include "lib/scenario/expression.hpp"
#include "lib/output/number_text.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include <muParser.h>

namespace impactbench::scenario {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

double floor_of(double x) {
  return std::floor(x);
}
double ceil_of(double x) {
  return std::ceil(x);
}
double modulo(double a, double b) {
  return a - b * std::floor(a / b);
}
double degrees_to_radians(double degrees) {
  return degrees * M_PI / 180.0;
}
// Index i of a triangle filled row by row, row r holding r + 1 items: i = r (r + 1)/2 + c.
// sqrt is exact on the perfect squares 8i + 1 = (2r + 1)^2, so the row boundaries are exact.
double triangle_row(double i) {
  return std::floor((std::sqrt(8.0 * std::floor(i) + 1.0) - 1.0) / 2.0);
}
double triangle_column(double i) {
  const double row = triangle_row(i);
  return std::floor(i) - row * (row + 1.0) / 2.0;
}

void define_functions(mu::Parser& parser) {
  parser.DefineFun("floor", floor_of);
  parser.DefineFun("ceil", ceil_of);
  parser.DefineFun("mod", modulo);
  parser.DefineFun("rad", degrees_to_radians);
  parser.DefineFun("rand", hashed_uniform);
  parser.DefineFun("tri_row", triangle_row);
  parser.DefineFun("tri_col", triangle_column);
}

std::string trim(std::string text) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string unknown_name_text(const std::string& name, std::size_t position,
                              const VariableTable& variables) {
  std::string known;
  for (const auto& each : variables.names()) known += (known.empty() ? "" : ", ") + each;
  return "unknown name '" + name + "' at position " + std::to_string(position) +
         " (known names: " + (known.empty() ? "none" : known) + ")";
}

std::string describe_error(const mu::Parser::exception_type& error,
                           const VariableTable& variables) {
  const std::string token = trim(error.GetToken());
  if (error.GetCode() == mu::ecUNASSIGNABLE_TOKEN)
    return unknown_name_text(token, static_cast<std::size_t>(error.GetPos()), variables);
  std::string message = error.GetMsg();
  if (!message.empty()) message[0] = static_cast<char>(std::tolower(message[0]));
  while (!message.empty() && message.back() == '.') message.pop_back();
  return message;
}

/// What the variable factory binds names against, and the first name it did not know.
struct NameBinding {
  VariableTable* variables;
  std::string unknown;
  double scratch;  // where an unknown name points until the error is raised
};

double* bind_name(const char* name, void* user_data) {
  auto& binding = *static_cast<NameBinding*>(user_data);
  if (binding.variables->contains(name)) return &binding.variables->at(name);
  if (binding.unknown.empty()) binding.unknown = name;
  return &binding.scratch;
}

/// The position of `name` as a whole identifier in `source` (0 when not found as one).
std::size_t identifier_position(const std::string& source, const std::string& name) {
  const auto is_word = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  for (std::size_t at = source.find(name); at != std::string::npos;
       at = source.find(name, at + 1)) {
    const std::size_t end = at + name.size();
    if ((at == 0 || !is_word(source[at - 1])) && (end == source.size() || !is_word(source[end])))
      return at;
  }
  return 0;
}

}  // namespace

double hashed_uniform(double i, double k) {
  const auto a = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(i)));
  const auto b = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::llround(k)));
  const std::uint64_t h = splitmix64(splitmix64(a) ^ (b * 0xD6E8FEB86659FD93ULL));
  return static_cast<double>(h >> 11) * 0x1.0p-53;  // 53 random bits -> [0, 1)
}

double& VariableTable::define(const std::string& name, double value) {
  double& slot = values_[name];
  slot = value;
  return slot;
}

double& VariableTable::at(const std::string& name) {
  const auto it = values_.find(name);
  if (it == values_.end()) throw std::out_of_range("no variable named '" + name + "'");
  return it->second;
}

std::vector<std::string> VariableTable::names() const {
  std::vector<std::string> names;
  for (const auto& [name, value] : values_) names.push_back(name);
  return names;
}

struct Expression::Impl {
  std::string source;
  std::unique_ptr<mu::Parser> parser;  // null for a constant
  double constant = 0.0;
  std::vector<std::string> used;
};

Expression::Expression(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Expression::Expression(const std::string& source, VariableTable& variables)
    : impl_(std::make_unique<Impl>()) {
  impl_->source = source;
  if (source.find_first_not_of(" \t") == std::string::npos)
    throw ExpressionError("empty expression");
  impl_->parser = std::make_unique<mu::Parser>();
  auto& parser = *impl_->parser;
  // Names are bound as the parser meets them (a variable factory), not all defined up front:
  // with n named values each of n expressions would otherwise define n variables (a chain of
  // 3,000 [derived] names took seconds to compile).
  NameBinding binding{&variables, {}, 0.0};
  try {
    define_functions(parser);
    parser.SetVarFactory(bind_name, &binding);
    parser.SetExpr(source);
    parser.Eval();  // compiles; reports syntax errors and unknown names now, not at run time
    for (const auto& [name, slot] : parser.GetUsedVar()) impl_->used.push_back(name);
  } catch (const mu::Parser::exception_type& error) {
    if (binding.unknown.empty())
      throw ExpressionError("bad expression '" + source + "': " + describe_error(error, variables));
  }
  if (!binding.unknown.empty())
    throw ExpressionError("bad expression '" + source + "': " +
                          unknown_name_text(binding.unknown,
                                            identifier_position(source, binding.unknown),
                                            variables));
}

Expression Expression::constant(double value) {
  auto impl = std::make_unique<Impl>();
  impl->source = output::number_text(value);
  impl->constant = value;
  return Expression(std::move(impl));
}

Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

double Expression::evaluate() const {
  if (!impl_->parser) return impl_->constant;
  try {
    return impl_->parser->Eval();
  } catch (const mu::Parser::exception_type& error) {  // e.g. a domain error inside a function
    throw ExpressionError("expression '" + impl_->source + "' failed: " + error.GetMsg());
  }
}

const std::vector<std::string>& Expression::used_variables() const {
  return impl_->used;
}
const std::string& Expression::source() const {
  return impl_->source;
}
bool Expression::is_constant() const {
  return !impl_->parser;
}

}  // namespace impactbench::scenario
