#pragma once
// One unilateral contact as the source's B.1 states it: gap h_n(q) >= 0 when open, the normal
// direction w_n = dh_n/dq, tangential directions W_t (one column planar, two spatial), the
// acceleration-level terms ẇ_nᵀv and Ẇ_tᵀv, friction μ and Newton restitution e.
//
// The generalized-force directions are stored sparsely, as blocks of consecutive velocity
// coordinates (a rigid-body contact touches at most two bodies), so that piles of thousands of
// bodies never form dense n-vectors. Row 0 of every block is w_nᵀ, rows 1..d are W_tᵀ.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace impactbench::model {

/// Identifies a contact across steps (warm starts, events CSV): the two bodies and the feature
/// (corner index, clipping point, ...). body_b = -1 means the static environment.
struct ContactKey {
  int body_a = -1;
  int body_b = -1;
  int feature = 0;
  friend bool operator==(const ContactKey&, const ContactKey&) = default;
  friend auto operator<=>(const ContactKey&, const ContactKey&) = default;
};

/// "(body_a, body_b, feature)": a key in a message.
inline std::string key_text(const ContactKey& key) {
  // Appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) on a literal before a temporary.
  std::string text = "(";
  text.append(std::to_string(key.body_a)).append(", ").append(std::to_string(key.body_b));
  text.append(", ").append(std::to_string(key.feature)).append(")");
  return text;
}

/// Whether a contact search writes each contact's name (find_contacts) or leaves it empty
/// (find_reachable_contacts: the time stepper names the contacts it reports on demand).
enum class ContactNaming { kNamed, kUnnamed };

/// A contact's key and gap h_n(q) [m] alone: what a guard on the gaps reads.
struct ContactGap {
  ContactKey key;
  double gap = 0.0;
};

/// Rows (1 + d) x cols of the contact Jacobian acting on velocities
/// [first_velocity, first_velocity + cols).
template <typename Scalar>
struct JacobianBlock {
  int first_velocity = 0;
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> rows;
};

template <typename Scalar>
struct Contact {
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  ContactKey key;
  std::string name;  ///< Human-readable, e.g. "ball-ground" or "C_L"; used in the events CSV.
  Scalar gap{0};     ///< h_n(q) [m], positive when open.
  std::vector<JacobianBlock<Scalar>> blocks;  ///< w_nᵀ (row 0) and W_tᵀ (rows 1..d), sparse.
  Scalar normal_drift{0};                     ///< ẇ_nᵀ v [m/s²]
  Vector tangent_drift;                       ///< Ẇ_tᵀ v [m/s²], size d
  double friction = 0.0;                      ///< μ ≥ 0
  double restitution = 0.0;                   ///< e ∈ [0, 1]
  Eigen::Vector3d point = Eigen::Vector3d::Zero();    ///< World contact point (for output only).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< World normal, pointing to body_a.

  int tangent_dim() const { return static_cast<int>(tangent_drift.size()); }

  /// Dense w_n (size nv).
  Vector normal_direction(int nv) const {
    Vector w(nv);
    write_normal_direction(w);
    return w;
  }
  /// Dense W_t (nv x d).
  Matrix tangent_directions(int nv) const {
    Matrix W(nv, tangent_dim());
    write_tangent_directions(W);
    return W;
  }
  /// w_n into a vector or column of size nv (overwritten), without a temporary.
  template <typename Out>
  void write_normal_direction(Out&& w) const {
    w.setZero();
    for (const auto& b : blocks)
      w.segment(b.first_velocity, b.rows.cols()) += b.rows.row(0).transpose();
  }
  /// W_t into an nv x d block (overwritten), without a temporary.
  template <typename Out>
  void write_tangent_directions(Out&& W) const {
    const int d = tangent_dim();
    W.setZero();
    for (const auto& b : blocks)
      W.block(b.first_velocity, 0, b.rows.cols(), d) += b.rows.bottomRows(d).transpose();
  }
  /// Local relative velocity [ζ_n, ζ_t] = [w_n W_t]ᵀ v (size 1 + d).
  template <typename Derived>
  Vector relative_velocity(const Eigen::MatrixBase<Derived>& v) const {
    Vector zeta = Vector::Zero(1 + tangent_dim());
    add_relative_velocity(v, zeta);
    return zeta;
  }
  /// zeta += [w_n W_t]ᵀ v, into any vector or column of size 1 + d: no temporary and no general
  /// product for blocks of (1 + d) × a few (the time stepper does this for every candidate).
  /// A rigid body's block (2 × 3 planar, 3 × 6 spatial) takes loops of fixed size, the same
  /// sums in the same order.
  template <typename Derived, typename Out>
  void add_relative_velocity(const Eigen::MatrixBase<Derived>& v, Out&& zeta) const {
    for (const auto& b : blocks) {
      if (b.rows.rows() == 2 && b.rows.cols() == 3)
        add_block_velocity<2, 3>(b, v, zeta);
      else if (b.rows.rows() == 3 && b.rows.cols() == 6)
        add_block_velocity<3, 6>(b, v, zeta);
      else
        add_block_velocity<Eigen::Dynamic, Eigen::Dynamic>(b, v, zeta);
    }
  }

 private:
  template <int Rows, int Cols, typename Derived, typename Out>
  static void add_block_velocity(const JacobianBlock<Scalar>& b,
                                 const Eigen::MatrixBase<Derived>& v, Out& zeta) {
    const Eigen::Index rows = Rows == Eigen::Dynamic ? b.rows.rows() : Rows;
    const Eigen::Index cols = Cols == Eigen::Dynamic ? b.rows.cols() : Cols;
    for (Eigen::Index col = 0; col < cols; ++col)
      for (Eigen::Index row = 0; row < rows; ++row)
        zeta(row) += b.rows(row, col) * v(b.first_velocity + col);
  }
};

}  // namespace impactbench::model
