#pragma once
// numpy arrays over buffers the library filled, without copying: the buffer is moved to the
// heap and a capsule owns it, so it lives as long as the array (or any view of it).
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <Eigen/Core>

#include "solvers/common/capacity_vector.hpp"

namespace impactbench::python {

/// A capsule that deletes `owned` when it goes, i.e. with the last array (or view) over it.
template <class T>
pybind11::capsule capsule_owning(std::unique_ptr<T> owned) {
  pybind11::capsule capsule(owned.get(), [](void* p) { delete static_cast<T*>(p); });
  owned.release();  // the capsule owns it now
  return capsule;
}

/// The array of shape `shape` (C order) over `data`, which it takes over.
template <class T>
pybind11::array_t<T> take_array(std::vector<T>&& data, std::vector<pybind11::ssize_t> shape) {
  auto owner = std::make_unique<std::vector<T>>(std::move(data));
  T* values = owner->data();
  return pybind11::array_t<T>(std::move(shape), values, capsule_owning(std::move(owner)));
}

/// A 1-D array over a vector of doubles that keeps its storage when moved (Eigen::VectorXd,
/// solvers::CapacityVector), which it takes over.
template <class Vector>
pybind11::array_t<double> take_vector_array(Vector&& vector) {
  static_assert(!std::is_reference_v<Vector>, "the vector is moved from, so pass an rvalue");
  auto owner = std::make_unique<Vector>(std::move(vector));
  const pybind11::ssize_t size = owner->size();
  double* values = owner->data();
  return pybind11::array_t<double>({size}, values, capsule_owning(std::move(owner)));
}

inline pybind11::array_t<double> take_array(Eigen::VectorXd&& vector) {
  return take_vector_array(std::move(vector));
}

inline pybind11::array_t<double> take_array(solvers::CapacityVector&& vector) {
  return take_vector_array(std::move(vector));
}

/// A 2-D array over an Eigen matrix (column-major, so the array is Fortran-ordered), which it
/// takes over.
inline pybind11::array_t<double> take_array(Eigen::MatrixXd&& matrix) {
  auto owner = std::make_unique<Eigen::MatrixXd>(std::move(matrix));
  const pybind11::ssize_t rows = owner->rows(), cols = owner->cols();
  const auto item = static_cast<pybind11::ssize_t>(sizeof(double));
  double* values = owner->data();
  return pybind11::array_t<double>({rows, cols}, {item, item * rows}, values,
                                   capsule_owning(std::move(owner)));
}

/// An array over `data`, which `owner` keeps alive (several arrays may share one owner).
template <class T>
pybind11::array_t<T> view_array(const std::shared_ptr<const void>& owner, const T* data,
                                std::vector<pybind11::ssize_t> shape) {
  return pybind11::array_t<T>(std::move(shape), data,
                              capsule_owning(std::make_unique<std::shared_ptr<const void>>(owner)));
}

}  // namespace impactbench::python
