#pragma once
// Python arguments turned into the program's own: a dict {key: value} into the "key=value"
// entries of --set and --option, read then by the same code as the command line's.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace impactbench::python {

/// "key=value" per item: floats as shortest round-trip text (read back exactly), bools as
/// true/false, ints and strings as written. Throws cli::CliError (usage) naming `flag` for a
/// key that is not a string or a value of another type.
std::vector<std::string> assignments(const pybind11::dict& items, const std::string& flag);

}  // namespace impactbench::python
