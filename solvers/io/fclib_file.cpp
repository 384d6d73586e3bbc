#include "solvers/io/fclib_file.hpp"

#include <hdf5.h>
// fclib.h declares C functions without extern "C" guards.
extern "C" {
#include <fclib.h>
}
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCholesky>

#include "solvers/friction/delassus_access.hpp"

namespace impactbench::solvers {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("FCLIB file " + path.string() + ": " + what);
}

/// Silences HDF5's automatic error printing while alive (fclib probes optional groups).
/// The first one also keeps HDF5 from cleaning up at process exit: after reading some corrupted
/// files (an object header that is not a dataset, found by the fuzz test) HDF5's shutdown
/// cannot release its internal lists and prints "HDF5: infinite loop closing library" and a
/// line of codes after our one-line error. The operating system frees the memory anyway.
class QuietHdf5 {
 public:
  QuietHdf5() {
    [[maybe_unused]] static const herr_t no_cleanup_at_exit = H5dont_atexit();
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

/// libfclib's delete functions free the contents of a problem but not the struct itself.
struct FclibLocalDeleter {
  void operator()(fclib_local* problem) const {
    fclib_delete_local(problem);
    std::free(problem);
  }
};
struct FclibGlobalDeleter {
  void operator()(fclib_global* problem) const {
    fclib_delete_global(problem);
    std::free(problem);
  }
};

/// Closes, when it goes, every HDF5 object opened while it lived: libfclib returns from some
/// failed reads of a corrupted file without closing the file or its datasets (found by the
/// fuzz test; a few hundred leaked files made HDF5 loop forever closing the library at exit).
class Hdf5ObjectsClosedAtEnd {
 public:
  Hdf5ObjectsClosedAtEnd() : before_(open_objects()) {}
  ~Hdf5ObjectsClosedAtEnd() {
    for (const hid_t id : open_objects()) {
      if (std::find(before_.begin(), before_.end(), id) != before_.end()) continue;
      switch (H5Iget_type(id)) {
        case H5I_FILE:
          H5Fclose(id);
          break;
        case H5I_GROUP:
          H5Gclose(id);
          break;
        case H5I_DATASET:
          H5Dclose(id);
          break;
        case H5I_DATATYPE:
          H5Tclose(id);
          break;
        case H5I_ATTR:
          H5Aclose(id);
          break;
        default:
          break;
      }
    }
  }
  Hdf5ObjectsClosedAtEnd(const Hdf5ObjectsClosedAtEnd&) = delete;
  Hdf5ObjectsClosedAtEnd& operator=(const Hdf5ObjectsClosedAtEnd&) = delete;

 private:
  static std::vector<hid_t> open_objects() {
    const ssize_t count = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
    if (count <= 0) return {};
    std::vector<hid_t> ids(static_cast<std::size_t>(count));
    const ssize_t listed =
        H5Fget_obj_ids(H5F_OBJ_ALL, H5F_OBJ_ALL, static_cast<std::size_t>(count), ids.data());
    ids.resize(listed < 0 ? 0 : static_cast<std::size_t>(listed));
    return ids;
  }
  std::vector<hid_t> before_;
};

/// Read-only HDF5 file for the structural checks made before libfclib reads it.
class Hdf5File {
 public:
  explicit Hdf5File(const std::filesystem::path& path) : path_(path) {
    if (!std::filesystem::exists(path)) fail(path, "does not exist");
    if (H5Fis_hdf5(path.c_str()) <= 0) fail(path, "is not an HDF5 file");
    id_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id_ < 0) fail(path, "cannot be opened");
  }
  ~Hdf5File() { H5Fclose(id_); }
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  bool has(const std::string& name) const {
    // Check each prefix: H5Lexists fails on a path whose parent group is missing.
    for (std::size_t slash = name.find('/', 1);; slash = name.find('/', slash + 1)) {
      const std::string prefix = name.substr(0, slash);
      if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      if (slash == std::string::npos) return true;
    }
  }
  /// Number of elements of a numeric dataset; fails if it is missing, not a dataset or not
  /// numbers (libfclib would stop the process on the failed read).
  long size(const std::string& name) const { return checked_size(name, Content::kNumbers); }
  /// Checks that an optional text dataset libfclib reads (info/title, ...) holds a string.
  void expect_text_if_present(const std::string& name) const {
    if (has(name)) checked_size(name, Content::kText);
  }
  /// Checks every member of an optional group: `text` names must be strings, the rest numbers.
  void expect_group_contents(const std::string& group, const std::vector<std::string>& text) const {
    if (!has(group)) return;
    H5O_info_t info{};
    if (H5Oget_info_by_name2(id_, group.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0 ||
        info.type != H5O_TYPE_GROUP)
      fail(path_, group + " is not a group");
    H5G_info_t members{};
    if (H5Gget_info_by_name(id_, group.c_str(), &members, H5P_DEFAULT) < 0)
      fail(path_, "cannot list " + group);
    for (hsize_t k = 0; k < members.nlinks; ++k) {
      char member[256] = {};
      if (H5Lget_name_by_idx(id_, group.c_str(), H5_INDEX_NAME, H5_ITER_INC, k, member,
                             sizeof member, H5P_DEFAULT) < 0)
        fail(path_, "cannot list " + group);
      const std::string name = group + "/" + member;
      const bool is_text = std::find(text.begin(), text.end(), member) != text.end();
      checked_size(name, is_text ? Content::kText : Content::kNumbers);
    }
  }
  int integer(const std::string& name) const {
    if (size(name) != 1) fail(path_, name + " must hold one integer");
    const hid_t dataset = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
    int value = 0;
    const herr_t status = H5Dread(dataset, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value);
    H5Dclose(dataset);
    if (status < 0) fail(path_, "cannot read " + name);
    return value;
  }
  void expect_size(const std::string& name, long expected) const {
    const long actual = size(name);
    if (actual != expected) {
      fail(path_, name + " has " + std::to_string(actual) + " entries, expected " +
                      std::to_string(expected));
    }
  }

 private:
  enum class Content { kNumbers, kText };

  long checked_size(const std::string& name, Content content) const {
    if (!has(name)) fail(path_, "missing dataset " + name);
    H5O_info_t info{};
    if (H5Oget_info_by_name2(id_, name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0 ||
        info.type != H5O_TYPE_DATASET)
      fail(path_, name + " is not a dataset");
    const hid_t dataset = H5Dopen2(id_, name.c_str(), H5P_DEFAULT);
    if (dataset < 0) fail(path_, "cannot open " + name);
    const hid_t type = H5Dget_type(dataset);
    const H5T_class_t type_class = type < 0 ? H5T_NO_CLASS : H5Tget_class(type);
    // No integer or floating-point type is wider than 16 bytes; a corrupted width (4 GB per
    // value, found by the fuzz test) would make HDF5 allocate a conversion buffer of that
    // width times the count, so such a dataset is not read.
    const bool sane_width = type >= 0 && H5Tget_size(type) <= 16;
    if (type >= 0) H5Tclose(type);
    const hid_t space = H5Dget_space(dataset);
    const hssize_t points = space < 0 ? -1 : H5Sget_simple_extent_npoints(space);
    if (space >= 0) H5Sclose(space);
    const bool numbers = type_class == H5T_INTEGER || type_class == H5T_FLOAT;
    const bool readable =
        points < 0 ||
        (content == Content::kNumbers
             ? !numbers || (sane_width && readable_numbers(dataset, static_cast<long>(points)))
             : type_class != H5T_STRING || readable_text(dataset, static_cast<long>(points)));
    H5Dclose(dataset);
    if (points < 0) fail(path_, "cannot read the size of " + name);
    if (content == Content::kNumbers && !numbers) fail(path_, name + " does not hold numbers");
    if (!readable) fail(path_, "cannot read the data of " + name);
    if (content == Content::kText && type_class != H5T_STRING)
      fail(path_, name + " does not hold text");
    return static_cast<long>(points);
  }

  /// Whether the `points` numbers of `dataset` can be read: libfclib exits the process when a
  /// read fails (a corrupted storage address, found by the fuzz test), so every numeric dataset
  /// is read once here first. A dataset claiming far more numbers than the file could hold
  /// (even compressed 64:1) is not read.
  bool readable_numbers(hid_t dataset, long points) const {
    std::error_code error;
    const auto bytes = std::filesystem::file_size(path_, error);
    if (error || static_cast<double>(points) > 8.0 * static_cast<double>(bytes)) return false;
    std::vector<double> values(static_cast<std::size_t>(points));
    return points == 0 ||
           H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
  }

  /// The same for a text dataset (fixed-length or variable-length strings).
  bool readable_text(hid_t dataset, long points) const {
    std::error_code error;
    const auto bytes = std::filesystem::file_size(path_, error);
    const hid_t type = H5Dget_type(dataset);
    if (error || type < 0 || static_cast<double>(points) > 8.0 * static_cast<double>(bytes)) {
      if (type >= 0) H5Tclose(type);
      return false;
    }
    bool ok = true;
    if (points > 0 && H5Tis_variable_str(type) > 0) {
      std::vector<char*> strings(static_cast<std::size_t>(points), nullptr);
      ok = H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, strings.data()) >= 0;
      if (ok) {
        const hid_t space = H5Dget_space(dataset);
        H5Dvlen_reclaim(type, space, H5P_DEFAULT, strings.data());
        H5Sclose(space);
      }
    } else if (points > 0) {
      const double size = static_cast<double>(H5Tget_size(type)) * static_cast<double>(points);
      ok = size <= 64.0 * static_cast<double>(bytes);
      if (ok) {
        std::vector<char> buffer(static_cast<std::size_t>(size));
        ok = H5Dread(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) >= 0;
      }
    }
    H5Tclose(type);
    return ok;
  }

  std::filesystem::path path_;
  hid_t id_ = -1;
};

/// Text fields of the info groups libfclib reads, if they exist.
void check_info(const Hdf5File& file, const std::string& problem) {
  file.expect_group_contents(problem + "/info", {"title", "description", "math_info"});
}

/// Matrix info groups (comment text; conditioning, determinant, rank numbers).
void check_matrix_info(const Hdf5File& file, const std::string& group) {
  file.expect_group_contents(group + "/info", {"comment"});
}

struct MatrixShape {
  int rows = 0;
  int cols = 0;
  long stored = 0;  ///< entries present in both i and x
};

/// Checks a CSparse matrix group (m, n, nz, nzmax, p, i, x) so that libfclib's reads fit.
MatrixShape check_matrix(const Hdf5File& file, const std::filesystem::path& path,
                         const std::string& group) {
  const int m = file.integer(group + "/m");
  const int n = file.integer(group + "/n");
  const int nz = file.integer(group + "/nz");
  const int nzmax = file.integer(group + "/nzmax");
  if (m < 0 || n < 0 || nzmax < 0) fail(path, group + " has negative dimensions");
  // libfclib allocates nzmax entries for i and x (nz for triplet p, i) and reads whole
  // datasets, so no dataset may be longer; the entries actually used are checked on reading.
  const auto expect_at_most = [&](const std::string& name, long limit) {
    const long actual = file.size(name);
    if (actual > limit) {
      fail(path, name + " has " + std::to_string(actual) + " entries, more than " +
                     std::to_string(limit));
    }
    return actual;
  };
  // libfclib allocates nzmax entries before reading and exits the process when that fails
  // (nzmax = 2^31 - 1): no matrix holds more than m·n entries, and the callers check m and n
  // against the vectors stored in the file before libfclib reads it.
  if (static_cast<double>(nzmax) > static_cast<double>(m) * static_cast<double>(n))
    fail(path, group + "/nzmax = " + std::to_string(nzmax) +
                   " exceeds m·n = " + std::to_string(static_cast<long long>(m) * n));
  check_matrix_info(file, group);
  long stored = 0;
  if (nz >= 0) {
    if (nz > nzmax) fail(path, group + " has nz > nzmax");
    file.expect_size(group + "/p", nz);
    file.expect_size(group + "/i", nz);
    stored = expect_at_most(group + "/x", nzmax);
    if (stored < nz) fail(path, group + "/x has fewer than nz entries");
  } else if (nz == -1 || nz == -2) {
    file.expect_size(group + "/p", (nz == -1 ? n : m) + 1L);
    stored = std::min(expect_at_most(group + "/i", nzmax), expect_at_most(group + "/x", nzmax));
  } else {
    fail(path, group + "/nz = " + std::to_string(nz) + " is not a known storage (>= 0, -1, -2)");
  }
  return {m, n, stored};
}

/// CSparse (triplet: i = rows, p = columns; compressed columns; compressed rows) to Eigen.
Eigen::SparseMatrix<double> to_eigen(const fclib_matrix& matrix, long stored,
                                     const std::filesystem::path& path, const std::string& name) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](long row, long col, double value) {
    if (row < 0 || row >= matrix.m || col < 0 || col >= matrix.n) {
      fail(path, name + " has an index outside its " + std::to_string(matrix.m) + "x" +
                     std::to_string(matrix.n) + " shape");
    }
    entries.emplace_back(static_cast<int>(row), static_cast<int>(col), value);
  };
  if (matrix.nz >= 0) {
    for (int k = 0; k < matrix.nz; ++k) add(matrix.i[k], matrix.p[k], matrix.x[k]);
  } else {
    const int outer = matrix.nz == -1 ? matrix.n : matrix.m;
    if (matrix.p[0] != 0 || matrix.p[outer] > stored) fail(path, name + " has bad pointers");
    for (int j = 0; j < outer; ++j) {
      if (matrix.p[j + 1] < matrix.p[j]) fail(path, name + " has decreasing pointers");
      for (int k = matrix.p[j]; k < matrix.p[j + 1]; ++k) {
        if (matrix.nz == -1) {
          add(matrix.i[k], j, matrix.x[k]);
        } else {
          add(j, matrix.i[k], matrix.x[k]);
        }
      }
    }
  }
  Eigen::SparseMatrix<double> result(matrix.m, matrix.n);
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

Eigen::VectorXd to_vector(const double* data, long size) {
  return Eigen::Map<const Eigen::VectorXd>(data, size);
}

int check_dimension(const Hdf5File& file, const std::filesystem::path& path,
                    const std::string& name) {
  const int dimension = file.integer(name);
  if (dimension != 2 && dimension != 3) {
    fail(path, name + " = " + std::to_string(dimension) + ", expected 2 or 3");
  }
  return dimension;
}

void read_local(const Hdf5File& file, const std::filesystem::path& path, FclibProblem& out) {
  const int dimension = check_dimension(file, path, "/fclib_local/spacedim");
  const MatrixShape shape = check_matrix(file, path, "/fclib_local/W");
  if (shape.rows != shape.cols || shape.rows % dimension != 0) {
    fail(path, "W is " + std::to_string(shape.rows) + "x" + std::to_string(shape.cols) +
                   ", expected square with a multiple of spacedim rows");
  }
  if (file.has("/fclib_local/V") || file.has("/fclib_local/R")) {
    fail(path, "mixed local problems (V, R) are not supported");
  }
  file.expect_size("/fclib_local/vectors/q", shape.rows);
  file.expect_size("/fclib_local/vectors/mu", shape.rows / dimension);
  check_info(file, "/fclib_local");
  const std::unique_ptr<fclib_local, FclibLocalDeleter> local(fclib_read_local(path.c_str()));
  if (!local) fail(path, "libfclib could not read the local problem");
  Eigen::SparseMatrix<double, Eigen::RowMajor> w = to_eigen(*local->W, shape.stored, path, "W");
  out.problem = FrictionProblem::sparse(dimension, std::move(w), to_vector(local->q, shape.rows),
                                        to_vector(local->mu, shape.rows / dimension));
  if (local->info != nullptr && local->info->title != nullptr) out.title = local->info->title;
  if (local->info != nullptr && local->info->description != nullptr) {
    out.description = local->info->description;
  }
}

GlobalFclibProblem read_global_matrices(const Hdf5File& file, const std::filesystem::path& path,
                                        FclibProblem* info) {
  GlobalFclibProblem result;
  result.dimension = check_dimension(file, path, "/fclib_global/spacedim");
  const MatrixShape m_shape = check_matrix(file, path, "/fclib_global/M");
  const MatrixShape h_shape = check_matrix(file, path, "/fclib_global/H");
  if (m_shape.rows != m_shape.cols) fail(path, "M is not square");
  if (h_shape.rows != m_shape.rows || h_shape.cols % result.dimension != 0) {
    fail(path, "H must have as many rows as M and a multiple of spacedim columns");
  }
  if (file.has("/fclib_global/G")) fail(path, "equality constraints (G, b) are not supported");
  file.expect_size("/fclib_global/vectors/f", m_shape.rows);
  file.expect_size("/fclib_global/vectors/w", h_shape.cols);
  file.expect_size("/fclib_global/vectors/mu", h_shape.cols / result.dimension);
  check_info(file, "/fclib_global");
  const std::unique_ptr<fclib_global, FclibGlobalDeleter> global(fclib_read_global(path.c_str()));
  if (!global) fail(path, "libfclib could not read the global problem");
  result.M = to_eigen(*global->M, m_shape.stored, path, "M");
  result.H = to_eigen(*global->H, h_shape.stored, path, "H");
  result.f = to_vector(global->f, m_shape.rows);
  result.w = to_vector(global->w, h_shape.cols);
  result.mu = to_vector(global->mu, h_shape.cols / result.dimension);
  if (info != nullptr && global->info != nullptr) {
    if (global->info->title != nullptr) info->title = global->info->title;
    if (global->info->description != nullptr) info->description = global->info->description;
  }
  return result;
}

void read_global(const Hdf5File& file, const std::filesystem::path& path, FclibProblem& out) {
  const GlobalFclibProblem global = read_global_matrices(file, path, &out);
  try {
    out.problem =
        reduce_global_problem(global.dimension, global.M, global.H, global.f, global.w, global.mu);
  } catch (const std::runtime_error& error) {
    fail(path, error.what());
  }
  out.from_global = true;
}

/// The reference solution: only when /solution holds every vector libfclib will read.
void read_reference(const Hdf5File& file, const std::filesystem::path& path, FclibProblem& out) {
  if (!file.has("/solution")) return;
  const long n = out.problem.size();
  if (!file.has("/solution/r") || !file.has("/solution/u")) return;
  file.expect_size("/solution/r", n);
  file.expect_size("/solution/u", n);
  if (out.from_global) {
    if (!file.has("/solution/v")) return;
    file.expect_size("/solution/v", file.integer("/fclib_global/M/n"));
  }
  fclib_solution* solution = fclib_read_solution(path.c_str());
  if (solution == nullptr) fail(path, "libfclib could not read /solution");
  out.reference_r = to_vector(solution->r, n);
  out.reference_u = to_vector(solution->u, n);
  fclib_delete_solutions(solution, 1);
}

}  // namespace

FrictionProblem reduce_global_problem(int dimension, const Eigen::SparseMatrix<double>& M,
                                      const Eigen::SparseMatrix<double>& H,
                                      const Eigen::VectorXd& f, const Eigen::VectorXd& w,
                                      const Eigen::VectorXd& mu) {
  if (M.rows() != M.cols() || H.rows() != M.rows() || f.size() != M.rows() ||
      w.size() != H.cols() || H.cols() != dimension * mu.size()) {
    throw std::runtime_error("global problem sizes disagree (M, H, f, w, mu)");
  }
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(M);
  if (cholesky.info() != Eigen::Success || !(cholesky.vectorD().minCoeff() > 0.0)) {
    throw std::runtime_error("mass matrix M is not symmetric positive definite");
  }
  const Eigen::SparseMatrix<double> m_inverse_h = cholesky.solve(H);
  Eigen::SparseMatrix<double, Eigen::RowMajor> delassus = H.transpose() * m_inverse_h;
  Eigen::VectorXd q = H.transpose() * cholesky.solve(f) + w;
  return FrictionProblem::sparse(dimension, std::move(delassus), std::move(q), mu);
}

GlobalFclibProblem read_fclib_global_matrices(const std::filesystem::path& path) {
  const QuietHdf5 quiet;
  const Hdf5ObjectsClosedAtEnd closed;
  const Hdf5File file(path);
  if (!file.has("/fclib_global")) fail(path, "has no /fclib_global problem");
  return read_global_matrices(file, path, nullptr);
}

bool is_hdf5_file(const std::filesystem::path& path) {
  const QuietHdf5 quiet;
  std::error_code error;
  return std::filesystem::is_regular_file(path, error) && H5Fis_hdf5(path.c_str()) > 0;
}

FclibProblem read_fclib_file(const std::filesystem::path& path) {
  const QuietHdf5 quiet;
  const Hdf5ObjectsClosedAtEnd closed;
  const Hdf5File file(path);
  FclibProblem result;
  if (file.has("/fclib_local")) {
    read_local(file, path, result);
  } else if (file.has("/fclib_global")) {
    read_global(file, path, result);
  } else {
    fail(path, "has neither /fclib_local nor /fclib_global");
  }
  read_reference(file, path, result);
  return result;
}

void write_fclib_local(const FrictionProblem& problem, const std::filesystem::path& path,
                       std::string_view title) {
  if (problem.dimension != 2 && problem.dimension != 3) fail(path, "dimension must be 2 or 3");
  if (problem.q.size() != problem.dimension * problem.mu.size()) {
    fail(path, "q and mu sizes disagree with the dimension");
  }
  // The local form holds W itself: a problem kept in its factors (a time stepper's) is written
  // with W = H A formed.
  if (problem.is_factored) {
    write_fclib_local(formed_delassus(problem), path, title);
    return;
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> w =
      problem.is_sparse ? problem.sparse_W : problem.dense_W.sparseView(0.0, 0.0);
  w.makeCompressed();
  if (w.rows() != problem.q.size() || w.cols() != problem.q.size())
    fail(path, "W has the wrong size");
  std::vector<int> pointers(w.outerIndexPtr(), w.outerIndexPtr() + w.rows() + 1);
  std::vector<int> columns(w.innerIndexPtr(), w.innerIndexPtr() + w.nonZeros());
  std::vector<double> values(w.valuePtr(), w.valuePtr() + w.nonZeros());
  Eigen::VectorXd q = problem.q.eval();
  Eigen::VectorXd mu = problem.mu.eval();

  fclib_matrix matrix{};
  matrix.nzmax = static_cast<int>(w.nonZeros());
  matrix.m = static_cast<int>(w.rows());
  matrix.n = static_cast<int>(w.cols());
  matrix.p = pointers.data();
  matrix.i = columns.data();
  matrix.x = values.data();
  matrix.nz = -2;  // compressed rows
  std::string title_text(title);
  std::string description = "written by impactbench";
  fclib_info info{title_text.data(), description.data(), nullptr};
  fclib_local local{};
  local.W = &matrix;
  local.mu = mu.data();
  local.q = q.data();
  local.spacedim = problem.dimension;
  local.info = &info;

  // libfclib opens an existing file for update, so the temporary must not exist beforehand.
  const std::filesystem::path temporary =
      path.string() + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  std::filesystem::remove(temporary);
  const QuietHdf5 quiet;
  if (fclib_write_local(&local, temporary.c_str()) != 1) {
    std::filesystem::remove(temporary);
    fail(path, "libfclib could not write the local problem");
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary);
    fail(path, "cannot rename the temporary file: " + error.message());
  }
}

}  // namespace impactbench::solvers
