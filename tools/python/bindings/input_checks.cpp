#include "tools/python/bindings/input_checks.hpp"

#include <cmath>

#include "lib/output/number_text.hpp"
#include "tools/cli/command.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

[[noreturn]] void refuse(const std::string& message) {
  throw cli::CliError(message, cli::kExitFailure);
}

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i)
    text += (i ? ", " : "") + std::to_string(array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

/// The array as C-ordered doubles, after checking its type is real numbers (not bool, complex,
/// strings or objects) and its dimensions.
py::array_t<double, py::array::c_style> as_doubles(const py::array& array, const std::string& name,
                                                   int ndim) {
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    refuse(name + ": dtype " + std::string(py::str(array.dtype())) +
           " is not a real number type (float or int)");
  if (array.ndim() != ndim)
    refuse(name + ": must have " + std::to_string(ndim) + " dimension" + (ndim > 1 ? "s" : "") +
           ", got shape " + shape_text(array));
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
}

void check_finite(const double* values, py::ssize_t size, const std::string& name) {
  for (py::ssize_t i = 0; i < size; ++i)
    if (!std::isfinite(values[i]))
      refuse(name + ": entry " + std::to_string(i) + " is not finite (" +
             output::number_text(values[i]) + ")");
}

std::vector<long> integers(const py::array& array, const std::string& name) {
  const char kind = array.dtype().kind();
  if ((kind != 'i' && kind != 'u') || array.ndim() != 1)
    refuse(name + ": must be a 1-D array of integers");
  const auto values = py::array_t<long, py::array::c_style | py::array::forcecast>::ensure(array);
  return {values.data(), values.data() + values.size()};
}

}  // namespace

void check_square(const std::string& name, long rows, long cols) {
  if (rows != cols || rows == 0)
    refuse(name + ": must be a non-empty square matrix, got shape (" + std::to_string(rows) + ", " +
           std::to_string(cols) + ")");
}

Eigen::MatrixXd dense_matrix(const py::array& array, const std::string& name) {
  const auto values = as_doubles(array, name, 2);
  check_finite(values.data(), values.size(), name);
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      values.data(), values.shape(0), values.shape(1));
}

RowSparse sparse_matrix(const py::array& data, const py::array& indices, const py::array& indptr,
                        long rows, long cols, const std::string& name) {
  const auto values = as_doubles(data, name + ".data", 1);
  check_finite(values.data(), values.size(), name + ".data");
  const std::vector<long> columns = integers(indices, name + ".indices");
  const std::vector<long> starts = integers(indptr, name + ".indptr");
  if (static_cast<long>(starts.size()) != rows + 1 || starts.front() != 0 ||
      starts.back() != static_cast<long>(columns.size()) ||
      static_cast<long>(columns.size()) != values.size())
    refuse(name + ": inconsistent compressed rows (indptr of " + std::to_string(starts.size()) +
           " entries for " + std::to_string(rows) + " rows, " + std::to_string(columns.size()) +
           " indices, " + std::to_string(values.size()) + " values)");
  RowSparse matrix(rows, cols);
  matrix.reserve(static_cast<Eigen::Index>(columns.size()));
  for (long row = 0; row < rows; ++row) {
    if (starts[row + 1] < starts[row])
      refuse(name + ": indptr decreases at row " + std::to_string(row));
    matrix.startVec(row);
    for (long k = starts[row]; k < starts[row + 1]; ++k) {
      const long col = columns[k];
      if (col < 0 || col >= cols || (k > starts[row] && col <= columns[k - 1]))
        refuse(name + ": column index " + std::to_string(col) + " of row " + std::to_string(row) +
               " is out of range or not increasing (call sort_indices())");
      matrix.insertBack(row, col) = values.data()[k];
    }
  }
  matrix.finalize();
  return matrix;
}

Eigen::VectorXd vector_of(const py::array& array, const std::string& name, long size,
                          const std::string& size_reason) {
  const auto values = as_doubles(array, name, 1);
  if (size >= 0 && values.size() != size)
    refuse(name + ": length " + std::to_string(values.size()) + " does not match " + size_reason +
           " (" + std::to_string(size) + ")");
  check_finite(values.data(), values.size(), name);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), values.size());
}

}  // namespace impactbench::python
