#pragma once
// Numbers as a person reads them and a program reads them back: the shortest text that
// round-trips the double exactly (std::to_chars), fixed or scientific whichever is shorter,
// with the exponent written without '+' or leading zeros (1e-4, 2.5e10, 0.001, 1000).
#include <string>

namespace impactbench::output {

std::string number_text(double value);

}  // namespace impactbench::output
