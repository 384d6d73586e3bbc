// solve_lcp(), solve_friction(), read_fclib(), read_lcp(): `impactbench solve` on matrices
// instead of a file. The same solver options (cli::solver_options: solver by name, defaults,
// --option settings), the same solvers and the same reported figures; a solver that does not
// converge is a status in the result, not an exception.
#include <cmath>
#include <filesystem>
#include <memory>
#include <utility>

#include <pybind11/stl.h>

#include "solvers/friction/friction_residual.hpp"
#include "solvers/friction/friction_solvers.hpp"
#include "solvers/io/fclib_file.hpp"
#include "solvers/io/lcp_text_file.hpp"
#include "solvers/lcp/lcp_solvers.hpp"
#include "tools/cli/command.hpp"
#include "tools/cli/setting_flags.hpp"
#include "tools/cli/solve_settings.hpp"
#include "tools/python/bindings/arguments.hpp"
#include "tools/python/bindings/arrays.hpp"
#include "tools/python/bindings/bindings.hpp"
#include "tools/python/bindings/errors.hpp"
#include "tools/python/bindings/input_checks.hpp"
#include "tools/python/bindings/interrupt.hpp"

namespace py = pybind11;

namespace impactbench::python {
namespace {

/// The matrix argument as Python hands it over: a dense array, or a CSR matrix's arrays.
struct MatrixArgument {
  std::optional<py::array> dense;
  std::optional<py::array> data, indices, indptr;
  long rows = 0, cols = 0;
};

MatrixArgument matrix_argument(const py::object& matrix) {
  MatrixArgument out;
  if (py::hasattr(matrix, "indptr") && py::hasattr(matrix, "format")) {  // scipy.sparse CSR
    const auto shape = matrix.attr("shape").cast<std::pair<long, long>>();
    out.rows = shape.first;
    out.cols = shape.second;
    out.data = py::array::ensure(matrix.attr("data"));
    out.indices = py::array::ensure(matrix.attr("indices"));
    out.indptr = py::array::ensure(matrix.attr("indptr"));
  } else {
    out.dense = py::array::ensure(matrix);
    if (!out.dense) throw cli::CliError("matrix: not an array", cli::kExitFailure);
    if (out.dense->ndim() == 2) {
      out.rows = out.dense->shape(0);
      out.cols = out.dense->shape(1);
    }
  }
  return out;
}

solvers::SolverOptions options_for(const std::string& solver, bool friction,
                                   std::optional<double> tol, std::optional<int> max_iter,
                                   const py::dict& options) {
  check_flag("--tol", cli::kPositiveFinite, tol);
  if (max_iter) check_flag("--max-iter", cli::kPositiveFinite, std::to_string(*max_iter));
  return cli::solver_options(solver, friction, tol, max_iter, assignments(options, "--option"));
}

py::dict result_dict(solvers::SolverResult&& result) {
  py::dict out;
  out["status"] = std::string(solvers::to_string(result.status));
  out["message"] = result.message;
  out["iterations"] = result.iterations;
  out["residual"] = result.residual;
  out["faceted_residual"] = std::isnan(result.faceted_residual)
                                ? py::object(py::none())
                                : py::object(py::float_(result.faceted_residual));
  out["seconds"] = result.seconds;
  out["converged"] = result.converged();
  out["solution"] = take_array(std::move(result.solution));
  out["velocity"] = take_array(std::move(result.velocity));
  return out;
}

/// Runs `solve` without the GIL, Ctrl-C polled from the solver's monitor.
template <class Solve>
solvers::SolverResult solve_interruptible(solvers::SolverOptions& options, Solve&& solve) {
  InterruptPoll interrupt;
  options.monitor = [&interrupt](int, double) {
    interrupt.poll();
    return true;
  };
  py::gil_scoped_release unlocked;
  return solve();
}

py::dict solve_lcp(const py::object& matrix, const py::object& q_argument,
                   const std::string& solver, std::optional<double> tol,
                   std::optional<int> max_iter, const py::dict& options,
                   const std::optional<py::object>& warm_start) {
  solvers::SolverOptions solver_options = options_for(solver, false, tol, max_iter, options);
  const MatrixArgument M = matrix_argument(matrix);
  solvers::LcpProblem problem;
  if (M.dense) {
    Eigen::MatrixXd dense = dense_matrix(*M.dense, "M");
    check_square("M", dense.rows(), dense.cols());
    problem = solvers::LcpProblem::dense(std::move(dense), {});
  } else {
    check_square("M", M.rows, M.cols);
    problem = solvers::LcpProblem::sparse(
        sparse_matrix(*M.data, *M.indices, *M.indptr, M.rows, M.cols, "M"), {});
  }
  const long n = problem.is_sparse ? problem.sparse_M.rows() : problem.dense_M.rows();
  problem.q = vector_of(py::array::ensure(q_argument), "q", n, "the rows of M");
  std::optional<Eigen::VectorXd> start;
  if (warm_start)
    start = vector_of(py::array::ensure(*warm_start), "warm_start", n, "the rows of M");
  return result_dict(solve_interruptible(solver_options, [&] {
    return solvers::solve_lcp(problem, solver, solver_options, start ? &*start : nullptr);
  }));
}

py::dict solve_friction(const py::object& matrix, const py::object& q_argument,
                        const py::object& mu_argument, const std::string& solver,
                        std::optional<double> tol, std::optional<int> max_iter,
                        const py::dict& options, const std::optional<py::object>& warm_start) {
  solvers::SolverOptions solver_options = options_for(solver, true, tol, max_iter, options);
  const MatrixArgument W = matrix_argument(matrix);
  solvers::FrictionProblem problem;
  long n = W.rows;
  Eigen::MatrixXd dense;
  RowSparse sparse;
  if (W.dense) {
    dense = dense_matrix(*W.dense, "W");
    n = dense.rows();
    check_square("W", dense.rows(), dense.cols());
  } else {
    check_square("W", W.rows, W.cols);
    sparse = sparse_matrix(*W.data, *W.indices, *W.indptr, W.rows, W.cols, "W");
  }
  Eigen::VectorXd q = vector_of(py::array::ensure(q_argument), "q", n, "the rows of W");
  Eigen::VectorXd mu = vector_of(py::array::ensure(mu_argument), "mu");
  const long contacts = mu.size();
  if (contacts == 0 || (n != 2 * contacts && n != 3 * contacts))
    throw cli::CliError("W: " + std::to_string(n) +
                            " rows are not 2 (planar) or 3 (spatial) per "
                            "contact for " +
                            std::to_string(contacts) + " coefficients in mu",
                        cli::kExitFailure);
  for (long i = 0; i < contacts; ++i)
    if (mu(i) < 0.0)
      throw cli::CliError("mu: entry " + std::to_string(i) + " is negative", cli::kExitFailure);
  const int dimension = static_cast<int>(n / contacts);
  problem = W.dense ? solvers::FrictionProblem::dense(dimension, std::move(dense), std::move(q),
                                                      std::move(mu))
                    : solvers::FrictionProblem::sparse(dimension, std::move(sparse), std::move(q),
                                                       std::move(mu));
  std::optional<Eigen::VectorXd> start;
  if (warm_start)
    start = vector_of(py::array::ensure(*warm_start), "warm_start", n, "the rows of W");
  return result_dict(solve_interruptible(solver_options, [&] {
    return solvers::solve_friction(problem, solver, solver_options, start ? &*start : nullptr);
  }));
}

void check_exists(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw cli::CliError(path + ": no such file", cli::kExitFailure);
}

/// A compressed-row matrix as its arrays, kept alive by `owner` (no copy).
py::dict csr_arrays(const std::shared_ptr<const void>& owner, const RowSparse& matrix) {
  py::dict out;
  const auto nonzeros = static_cast<py::ssize_t>(matrix.nonZeros());
  out["shape"] = py::make_tuple(matrix.rows(), matrix.cols());
  out["data"] = view_array(owner, matrix.valuePtr(), {nonzeros});
  out["indices"] = view_array(owner, matrix.innerIndexPtr(), {nonzeros});
  out["indptr"] = view_array(owner, matrix.outerIndexPtr(), {matrix.rows() + 1});
  return out;
}

py::dict read_fclib(const std::string& path) {
  check_exists(path);
  auto file = std::make_shared<solvers::FclibProblem>(solvers::read_fclib_file(path));
  file->problem.sparse_W.makeCompressed();
  const std::shared_ptr<const void> owner = file;
  const solvers::FrictionProblem& p = file->problem;
  py::dict out;
  out["dimension"] = p.dimension;
  out["W"] = csr_arrays(owner, p.sparse_W);
  out["q"] = view_array(owner, p.q.data(), {p.q.size()});
  out["mu"] = view_array(owner, p.mu.data(), {p.mu.size()});
  out["title"] = file->title;
  out["description"] = file->description;
  out["from_global"] = file->from_global;
  out["reference_r"] =
      file->reference_r
          ? py::object(view_array(owner, file->reference_r->data(), {file->reference_r->size()}))
          : py::object(py::none());
  out["reference_u"] =
      file->reference_u
          ? py::object(view_array(owner, file->reference_u->data(), {file->reference_u->size()}))
          : py::object(py::none());
  out["reference_residual"] =
      file->reference_r ? py::object(py::float_(solvers::friction_residual(p, *file->reference_r)))
                        : py::object(py::none());
  return out;
}

py::dict read_lcp(const std::string& path) {
  check_exists(path);
  auto problem = std::make_shared<solvers::LcpProblem>(solvers::io::read_lcp_file(path));
  problem->sparse_M.makeCompressed();
  const std::shared_ptr<const void> owner = problem;
  py::dict out;
  const auto n = static_cast<py::ssize_t>(problem->size());
  if (problem->is_sparse)
    out["M"] = csr_arrays(owner, problem->sparse_M);
  else  // Eigen's dense matrices are column-major: the array is its transpose's view, in C order
    out["M"] = view_array(owner, problem->dense_M.data(), {n, n}).attr("T");
  out["q"] = view_array(owner, problem->q.data(), {n});
  return out;
}

}  // namespace

void add_solver_functions(py::module_& m) {
  m.def("_solve_lcp", &solve_lcp, py::arg("M"), py::arg("q"), py::arg("solver"),
        py::arg("tol") = py::none(), py::arg("max_iter") = py::none(),
        py::arg("options") = py::dict(), py::arg("warm_start") = py::none());
  m.def("_solve_friction", &solve_friction, py::arg("W"), py::arg("q"), py::arg("mu"),
        py::arg("solver"), py::arg("tol") = py::none(), py::arg("max_iter") = py::none(),
        py::arg("options") = py::dict(), py::arg("warm_start") = py::none());
  m.def("_read_fclib", &read_fclib, py::arg("path"));
  m.def("_read_lcp", &read_lcp, py::arg("path"));
}

}  // namespace impactbench::python
