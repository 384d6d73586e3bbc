#pragma once
// Arithmetic expressions in scenario files ("height - radius", "push_rate*t", "rand(i, 0)"),
// compiled once by muParser and evaluated many times against named variable slots.
//
// Besides muParser's operators (+ - * / ^, comparisons, a ? b : c) and functions (sin, cos,
// tan, asin, acos, atan, sqrt, exp, ln, log10, abs, sign, rint, min, max, sum, avg) and the
// constants _pi and _e, every expression may call
//   floor(x), ceil(x)   rounding
//   mod(a, b)           a - b floor(a/b) (result has the sign of b)
//   rad(x)              degrees to radians
//   rand(i, k)          a deterministic uniform number in [0, 1) hashed from the integers
//                       nearest to i and k (splitmix64), the same on every platform; piles use
//                       it for reproducible random placement.
//   tri_row(i), tri_col(i)  row r and column c of item i in a triangle filled row by row,
//                       row r holding r + 1 items (i = r (r + 1)/2 + c): pyramids.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace impactbench::scenario {

/// Thrown for an expression that does not compile; the message says what and where in the
/// expression, without any file location (the loader adds it).
class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Named double slots with stable addresses. Expressions bind to the slots that exist when
/// they are compiled and read the current values whenever they are evaluated.
class VariableTable {
 public:
  /// Creates the slot (or overwrites its value) and returns it.
  double& define(const std::string& name, double value = 0.0);
  bool contains(const std::string& name) const { return values_.count(name) != 0; }
  double& at(const std::string& name);
  std::vector<std::string> names() const;

 private:
  friend class Expression;
  std::map<std::string, double> values_;  // node-based: slot addresses never move
};

class Expression {
 public:
  /// Compiles `source` against the slots of `variables`, which must outlive the expression.
  /// Throws ExpressionError on a syntax error or an unknown name.
  Expression(const std::string& source, VariableTable& variables);
  /// An expression that always yields `value` (a plain number in the file).
  static Expression constant(double value);

  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  ~Expression();

  double evaluate() const;
  /// The variables this expression reads (sorted).
  const std::vector<std::string>& used_variables() const;
  /// The source text, or the number printed with full precision for a constant.
  const std::string& source() const;
  bool is_constant() const;

 private:
  struct Impl;
  explicit Expression(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// The value rand(i, k) of the expressions, exposed for tests and for code that mirrors them.
double hashed_uniform(double i, double k);

}  // namespace impactbench::scenario
