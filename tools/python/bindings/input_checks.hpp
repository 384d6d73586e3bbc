#pragma once
// The matrices and vectors given to the solvers, checked before any solver runs: a real number
// type, the number of dimensions, the shape against the other arguments, every entry finite;
// each refusal is one line naming the argument (impactbench.Error, exit code 1 as for a bad
// problem file).
#include <string>

#include <pybind11/numpy.h>
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace impactbench::python {

using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// A 2-D array of real numbers, every entry finite.
Eigen::MatrixXd dense_matrix(const pybind11::array& array, const std::string& name);

/// A compressed-row matrix (scipy.sparse.csr_matrix's data, indices, indptr) of `rows` ×
/// `cols`, indices in range and increasing along each row, every value finite.
RowSparse sparse_matrix(const pybind11::array& data, const pybind11::array& indices,
                        const pybind11::array& indptr, long rows, long cols,
                        const std::string& name);

/// A 1-D array of real numbers, every entry finite; `size` >= 0 also fixes its length, and
/// `size_reason` says where that length comes from ("M's rows").
Eigen::VectorXd vector_of(const pybind11::array& array, const std::string& name, long size = -1,
                          const std::string& size_reason = "");

/// Throws unless the matrix `name` is square with `rows` rows.
void check_square(const std::string& name, long rows, long cols);

}  // namespace impactbench::python
