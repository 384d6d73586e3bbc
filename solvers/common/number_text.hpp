#pragma once
// Numbers as a person reads them and a program reads them back: the shortest text that
// round-trips the double exactly (std::to_chars), fixed or scientific whichever is shorter,
// with the exponent written without '+' or leading zeros (1e-4, 2.5e10, 0.001, 1000). The one
// number formatter of the project: the solvers' messages, the CSV writers and every error message
// (it sits in the lowest layer, which depends on nothing but the standard library and Eigen).
#include <string>

namespace impactbench::output {

/// Longest text number_chars writes ("-2.2250738585072014e-308" and the like, with room).
inline constexpr int kNumberTextCapacity = 32;

/// Writes the text of `value` at `first` (at least kNumberTextCapacity chars) without a
/// terminating zero; returns one past its last char. What number_text and the CSV writers use.
char* number_chars(char* first, double value);

std::string number_text(double value);

}  // namespace impactbench::output
