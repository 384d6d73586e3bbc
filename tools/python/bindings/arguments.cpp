#include "tools/python/bindings/arguments.hpp"

#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"

namespace py = pybind11;

namespace impactbench::python {

std::vector<std::string> assignments(const py::dict& items, const std::string& flag) {
  std::vector<std::string> out;
  for (const auto& [key, value] : items) {
    if (!py::isinstance<py::str>(key))
      throw cli::CliError(flag + ": keys must be strings, got " +
                              std::string(py::str(py::type::of(key).attr("__name__"))),
                          cli::kExitUsage);
    std::string text;
    if (py::isinstance<py::bool_>(value))
      text = value.cast<bool>() ? "true" : "false";
    else if (py::isinstance<py::int_>(value) || py::isinstance<py::str>(value))
      text = py::str(value);
    else if (py::isinstance<py::float_>(value))
      text = output::number_text(value.cast<double>());
    else
      throw cli::CliError(flag + " " + key.cast<std::string>() +
                              ": a value must be a number, a bool or a string, got " +
                              std::string(py::str(py::type::of(value).attr("__name__"))),
                          cli::kExitUsage);
    out.push_back(key.cast<std::string>() + "=" + text);
  }
  return out;
}

}  // namespace impactbench::python
