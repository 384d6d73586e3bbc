#pragma once
// impactbench.Error: every failure the program reports as one line on stderr reaches Python as
// this exception (a subclass of RuntimeError and ValueError) with the same line and the
// program's exit code as `exit_code`; Ctrl-C is KeyboardInterrupt.
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace CLI {
class Validator;
}

namespace impactbench::python {

/// Creates impactbench.Error on the module and registers the translation of C++ exceptions.
void register_errors(pybind11::module_& m);

/// Checks a value given for `flag` as the program's option check does (the same validator on
/// the value's shortest round-trip text); throws cli::CliError (usage) with the program's line.
void check_flag(const std::string& flag, const CLI::Validator& validator, const std::string& text);
void check_flag(const std::string& flag, const CLI::Validator& validator,
                const std::optional<double>& value);

}  // namespace impactbench::python
