#pragma once
// A vector of doubles that keeps its storage when its size changes: resize allocates only
// beyond its capacity, which then at least doubles. Eigen's VectorXd frees and allocates at every
// change of size, so a problem whose size follows a time stepper's active contacts would allocate
// at almost every step of a pile whose contacts come and go.
//
// It is an Eigen expression over storage of its own: a Map, aligned as a VectorXd's storage is,
// so that Eigen reads it with the same kernels as a VectorXd and every sum comes out the same to
// the bit; code written for a VectorXd reads it unchanged. The Map is pointed at the storage by
// placement new, as Eigen's own Ref is. Like a VectorXd it takes its size from what is assigned
// to it; noalias() is replaced by assign_noalias(), which sizes it first (a Map's noalias()
// would write past its end).
#include <algorithm>
#include <new>

#include <Eigen/Core>

namespace impactbench::solvers {

class CapacityVector : public Eigen::Map<Eigen::VectorXd, Eigen::Aligned16> {
 public:
  using Base = Eigen::Map<Eigen::VectorXd, Eigen::Aligned16>;

  CapacityVector() noexcept : Base(nullptr, 0) {}
  explicit CapacityVector(Eigen::Index size) : CapacityVector() { resize(size); }
  CapacityVector(const CapacityVector& other) : CapacityVector() { assign(other); }
  CapacityVector(CapacityVector&& other) noexcept : CapacityVector() { swap(other); }
  // Implicit, as a VectorXd is made from any expression.
  template <typename Derived>
  CapacityVector(const Eigen::DenseBase<Derived>& other)  // NOLINT(google-explicit-constructor)
      : CapacityVector() {
    assign(other);
  }
  ~CapacityVector() = default;

  CapacityVector& operator=(const CapacityVector& other) {
    if (this != &other) assign(other);
    return *this;
  }
  CapacityVector& operator=(CapacityVector&& other) noexcept {
    swap(other);
    return *this;
  }
  template <typename Derived>
  CapacityVector& operator=(const Eigen::DenseBase<Derived>& other) {
    assign(other);
    return *this;
  }

  /// The values are not kept (as with VectorXd::resize). Storage that must grow at least
  /// doubles, so that a size rising slowly (a pile's contacts while it forms) reallocates
  /// O(log size) times, as the project's other kept buffers do (lib/model/growing_capacity.hpp).
  void resize(Eigen::Index size) {
    if (size > storage_.size()) storage_.resize(grown_capacity(size));
    remap(size);
  }
  /// The first min(old, new) values are kept.
  void conservativeResize(Eigen::Index size) {
    reserve(size);
    remap(size);
  }
  /// Storage for `size` values, the size and the values kept: a later resize up to it does not
  /// allocate.
  void reserve(Eigen::Index size) {
    if (size > storage_.size()) storage_.conservativeResize(grown_capacity(size));
    remap(this->size());
  }
  void setZero(Eigen::Index size) {
    resize(size);
    Base::setZero();
  }
  void setZero() { Base::setZero(); }
  /// The size it can take without allocating.
  Eigen::Index capacity() const { return storage_.size(); }

  /// Sized to `expression`, then `expression` is evaluated straight into it (which must not
  /// read this vector), as `vector.noalias() = expression` does for a VectorXd.
  template <typename Expression>
  void assign_noalias(const Expression& expression) {
    resize(expression.rows());
    Base::noalias() = expression;
  }
  /// `expression` (of this vector's size, not reading it) added straight into it, as
  /// `vector.noalias() += expression` does for a VectorXd.
  template <typename Expression>
  void add_noalias(const Expression& expression) {
    eigen_assert(expression.rows() == this->size());
    Base::noalias() += expression;
  }
  void noalias() = delete;  // it would not resize: assign_noalias, add_noalias

  /// Exchanges the storage (Map's own swap would exchange the values of equal sizes).
  void swap(CapacityVector& other) noexcept {
    storage_.swap(other.storage_);
    const Eigen::Index size = this->size();
    remap(other.size());
    other.remap(size);
  }
  template <typename Other>
  void swap(Other&&) = delete;

 private:
  template <typename Derived>
  void assign(const Eigen::DenseBase<Derived>& other) {
    // An expression that reads this vector is safe as long as it does not grow it beyond its
    // capacity (as with a VectorXd, whose resize frees the storage the expression reads).
    resize(other.size());
    Base::operator=(other);
  }
  Eigen::Index grown_capacity(Eigen::Index size) const {
    return std::max(size, 2 * storage_.size());
  }
  void remap(Eigen::Index size) noexcept {
    new (static_cast<Base*>(this)) Base(storage_.data(), size);
  }

  Eigen::VectorXd storage_;
};

/// A read-only view of the values of a VectorXd or a CapacityVector, made from either without a
/// copy and aligned as both are, so that Eigen reads it with a VectorXd's kernels (the same bits).
/// Unlike Eigen::Ref<const VectorXd>, it binds nothing else: a caller with an expression
/// evaluates it first, so that no copy is made where nobody sees it.
class VectorView : public Eigen::Map<const Eigen::VectorXd, Eigen::Aligned16> {
 public:
  using Base = Eigen::Map<const Eigen::VectorXd, Eigen::Aligned16>;
  VectorView(const Eigen::VectorXd& vector)  // NOLINT(google-explicit-constructor)
      : Base(vector.data(), vector.size()) {}
  VectorView(const CapacityVector& vector)  // NOLINT(google-explicit-constructor)
      : Base(vector.data(), vector.size()) {}
};

}  // namespace impactbench::solvers
