#include "tools/python/bindings/errors.hpp"

#include <new>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "lib/output/message_text.hpp"
#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"
#include "tools/compare/run_process.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

// The exception type, created once at import and kept for the interpreter's lifetime.
PyObject* error_type = nullptr;

/// Raises impactbench.Error with `message` (made one printable line, as main() prints it).
void raise_error(const char* message, int exit_code) {
  const std::string line = output::printable(message, 600);
  py::object error = py::reinterpret_borrow<py::object>(error_type)(line);
  error.attr("exit_code") = exit_code;
  PyErr_SetObject(error_type, error.ptr());
}

}  // namespace

void register_errors(py::module_& m) {
  // class Error(RuntimeError, ValueError): caught by either, and by `except impactbench.Error`.
  py::tuple bases = py::make_tuple(py::handle(PyExc_RuntimeError), py::handle(PyExc_ValueError));
  error_type = PyErr_NewExceptionWithDoc(
      "impactbench.Error",
      "A failure the impactbench program reports as one line on stderr: the same line is the "
      "message, the program's exit code is `exit_code` (1 bad data or failed run, 2 usage).",
      bases.ptr(), nullptr);
  if (!error_type) throw py::error_already_set();
  m.add_object("Error", py::handle(error_type));
  // The program's main() catches these in the same order (tools/cli/main.cpp).
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const py::error_already_set&) {
      throw;  // a Python exception (KeyboardInterrupt from the signal poll) passes unchanged
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const cli::CliError& error) {
      raise_error(error.what(), error.exit_code());
    } catch (const compare::ProcessInterrupted&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const std::bad_alloc&) {
      raise_error("out of memory (the run or the file needs more memory than is available)",
                  cli::kExitFailure);
    } catch (const std::exception& error) {
      raise_error(error.what(), cli::kExitFailure);
    }
  });
}

void check_flag(const std::string& flag, const CLI::Validator& validator, const std::string& text) {
  std::string value = text;
  const std::string problem = validator(value);
  if (!problem.empty()) throw cli::CliError(flag + ": " + problem, cli::kExitUsage);
}

void check_flag(const std::string& flag, const CLI::Validator& validator,
                const std::optional<double>& value) {
  if (value) check_flag(flag, validator, output::number_text(*value));
}

}  // namespace impactbench::python
