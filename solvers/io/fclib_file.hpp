#pragma once
// FCLIB problem files (HDF5, Acary–Brémond–Huber 2018) read through Debian's libfclib.
// Local form: u = W r + q. Global form: M v = H r + f, u = Hᵀ v + w, reduced on reading to
//   W = Hᵀ M⁻¹ H,  q = Hᵀ M⁻¹ f + w   (sparse Cholesky of M, never a dense inverse).
// libfclib terminates the process on a malformed file, so every dataset it will read is
// checked first (presence, sizes) with HDF5 directly; any problem throws std::runtime_error
// naming the file and what is wrong.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/SparseCore>

#include "solvers/friction/friction_problem.hpp"

namespace impactbench::solvers {

struct FclibProblem {
  FrictionProblem problem;  ///< local form, block-sparse W (global files already reduced)
  bool from_global = false;
  std::string title;
  std::string description;
  std::optional<Eigen::VectorXd> reference_r;  ///< /solution/r when the file carries one
  std::optional<Eigen::VectorXd> reference_u;  ///< /solution/u when the file carries one
};

/// The global form as stored: M v = H r + f, u = Hᵀ v + w.
struct GlobalFclibProblem {
  int dimension = 3;
  Eigen::SparseMatrix<double> M;  ///< dofs × dofs, SPD
  Eigen::SparseMatrix<double> H;  ///< dofs × (dimension · contacts)
  Eigen::VectorXd f;
  Eigen::VectorXd w;
  Eigen::VectorXd mu;
};

/// Reads the matrices of a global FCLIB problem without reducing them.
GlobalFclibProblem read_fclib_global_matrices(const std::filesystem::path& path);

/// Reads a local or global FCLIB problem (and its reference solution when present).
FclibProblem read_fclib_file(const std::filesystem::path& path);

/// Whether `path` is an HDF5 file, by its signature (whatever its name ends with).
bool is_hdf5_file(const std::filesystem::path& path);

/// Reduction of the global form: W = Hᵀ M⁻¹ H, q = Hᵀ M⁻¹ f + w. Throws std::runtime_error if
/// M is not symmetric positive definite (Cholesky fails) or sizes disagree.
FrictionProblem reduce_global_problem(int dimension, const Eigen::SparseMatrix<double>& M,
                                      const Eigen::SparseMatrix<double>& H,
                                      const Eigen::VectorXd& f, const Eigen::VectorXd& w,
                                      const Eigen::VectorXd& mu);

/// Writes the problem in local form (W as compressed rows; a factored problem's W = H A formed)
/// to a temporary file next to `path` and renames it over `path`, so readers never see a
/// partial file.
void write_fclib_local(const FrictionProblem& problem, const std::filesystem::path& path,
                       std::string_view title = "impactbench problem");

}  // namespace impactbench::solvers
