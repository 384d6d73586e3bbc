#pragma once
// Numbers as text (number_text, number_chars): defined with the solvers, the lowest layer, so that
// every layer writes numbers one way.
#include "solvers/common/number_text.hpp"
