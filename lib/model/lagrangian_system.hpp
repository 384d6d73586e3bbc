#pragma once
// The mechanical system of the source's B.2, in the project's sign convention:
//     M(q) v̇ + H(q, v) = S(q) u + Σ_i (w_n,i λ_n,i + W_t,i λ_t,i).
// H holds gravity, Coriolis/centrifugal terms, springs and dampers. Positions q may have more
// coordinates than velocities v (unit quaternions), related by q̇ = N(q) v.
//
// Templated on the scalar so that the sensitivity module can evaluate every quantity with a
// forward-mode automatic-differentiation scalar (Eigen::AutoDiffScalar): implementations must
// not branch on anything but geometry decisions that are constant in a neighbourhood.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "lib/model/autodiff.hpp"
#include "lib/model/contact.hpp"

namespace impactbench::model {

/// The key and gap (its value) of each contact, in order, into `out` (cleared).
template <typename Scalar>
void write_contact_gaps(const std::vector<Contact<Scalar>>& contacts,
                        std::vector<ContactGap>& out) {
  out.clear();
  for (const Contact<Scalar>& c : contacts) out.push_back({c.key, value_of(c.gap)});
}

template <typename Scalar>
class LagrangianSystem {
 public:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using SparseMatrix = Eigen::SparseMatrix<Scalar>;

  virtual ~LagrangianSystem() = default;

  virtual int num_positions() const = 0;        ///< nq
  virtual int num_velocities() const = 0;       ///< nv
  virtual int num_inputs() const { return 0; }  ///< nu
  virtual int tangent_dim() const = 0;          ///< 1 planar, 2 spatial

  /// M(q), nv x nv, symmetric positive definite (block diagonal for free rigid bodies).
  virtual SparseMatrix mass_matrix(const Vector& q) const = 0;
  /// M(q) into `M`: a system that can fill it in place reuses its storage (a time stepper forms
  /// M every step when it depends on q).
  virtual void write_mass_matrix(const Vector& q, SparseMatrix& M) const { M = mass_matrix(q); }
  /// True when M does not depend on q (free planar rigid bodies), so that a time stepper may
  /// factor it once. False unless a system says so.
  virtual bool mass_matrix_is_constant() const { return false; }
  /// H(q, v), nv.
  virtual Vector bias_forces(const Vector& q, const Vector& v) const = 0;
  /// H(q, v) into `out` (resized): a system that can fill it in place reuses its storage (a time
  /// stepper needs H every step).
  virtual void write_bias_forces(const Vector& q, const Vector& v, Vector& out) const {
    out = bias_forces(q, v);
  }
  /// True when H does not depend on q or v (gravity alone, as on free planar rigid bodies), so
  /// that an integrator may evaluate it once. False unless a system says so.
  virtual bool bias_forces_are_constant() const { return false; }
  /// True when damping_matrix may be non-empty (a time stepper asks for it only then).
  virtual bool has_damping_matrix() const { return false; }
  /// ∂H/∂v (nv x nv) of the velocity-dependent forces the system differentiates in closed form
  /// (dampers), or an empty matrix when H does not depend on v or the system does not say. Time
  /// steppers use it to take those forces implicitly without extra evaluations of H.
  virtual SparseMatrix damping_matrix(const Vector& q, const Vector& v) const {
    (void)q;
    (void)v;
    return SparseMatrix();
  }
  /// S(q), nv x nu; the generalized force of the input is S(q) u.
  virtual Matrix input_matrix(const Vector& q) const {
    (void)q;
    return Matrix::Zero(num_velocities(), num_inputs());
  }

  /// q̇ = N(q) v.
  virtual Vector position_rate(const Vector& q, const Vector& v) const = 0;
  /// position_rate(q, v) into `out` (nq), without a temporary where the system can (an
  /// event-driven flow needs it at every right-hand side).
  virtual void write_position_rate(const Vector& q, const Vector& v, Eigen::Ref<Vector> out) const {
    out = position_rate(q, v);
  }
  /// q advanced by h with constant v; keeps unit quaternions unit (exponential map).
  virtual Vector integrate_position(const Vector& q, const Vector& v, const Scalar& h) const = 0;
  /// integrate_position(q, v, h) into `out` (resized; not q or v itself), reusing its storage.
  virtual void write_integrated_position(const Vector& q, const Vector& v, const Scalar& h,
                                         Vector& out) const {
    out = integrate_position(q, v, h);
  }

  /// Contacts whose gap is below `margin` [m] (all potential contacts of small systems may be
  /// returned regardless). v is needed for the ẇᵀv terms. Clears and fills `out`.
  virtual void find_contacts(const Vector& q, const Vector& v, double margin,
                             std::vector<Contact<Scalar>>& out) const = 0;

  /// The key and gap of each contact find_contacts(q, v, margin, ·) finds, in the same order and
  /// to the bit, without the rest of each contact (Jacobians, drift terms, names): what the
  /// event-driven integrator's guards read between events. Clears and fills `out`. This default
  /// finds the whole contacts; a system that can form the gaps alone overrides it.
  virtual void find_contact_gaps(const Vector& q, const Vector& v, double margin,
                                 std::vector<ContactGap>& out) const {
    thread_local std::vector<Contact<Scalar>> contacts;  // storage kept between calls
    find_contacts(q, v, margin, contacts);
    write_contact_gaps(contacts, out);
  }

  /// The contacts that may come within `margin` [m] while every body moves for a time `horizon`
  /// [s] at velocities bounded by `speed_bound` (per velocity coordinate, |v_i| ≤ speed_bound_i):
  /// each contact whose gap at q is below margin plus the largest displacement the bound allows
  /// of the points of its two bodies. One search where a time stepper would otherwise search at
  /// the predicted state and again at q. Returns false, leaving `out` alone, when the system
  /// cannot bound its contacts' motion; callers then search twice.
  /// The contacts' names are left empty: the time stepper names only those it reports, with
  /// write_contact_name (a name written per candidate and step is one more cache line per
  /// contact in a pile's every step).
  virtual bool find_reachable_contacts(const Vector& q, const Vector& v,
                                       const Eigen::VectorXd& speed_bound, double horizon,
                                       double margin, std::vector<Contact<Scalar>>& out) const {
    (void)q;
    (void)v;
    (void)speed_bound;
    (void)horizon;
    (void)margin;
    (void)out;
    return false;
  }

  /// The name find_contacts gives the contact with `key` ("ball-ground"), into `name` (its
  /// storage kept). A system that overrides find_reachable_contacts overrides this too; this
  /// default, for the others, names the key's numbers.
  virtual void write_contact_name(const ContactKey& key, std::string& name) const {
    name = "contact " + key_text(key);
  }
  /// c's name as the search was asked: written (write_contact_name) or left empty.
  void name_contact(ContactNaming naming, Contact<Scalar>& c) const {
    if (naming == ContactNaming::kNamed)
      write_contact_name(c.key, c.name);
    else
      c.name.clear();
  }

  /// Kinetic plus potential energy (springs, gravity) [J].
  virtual Scalar energy(const Vector& q, const Vector& v) const = 0;

  /// Column names of the trajectory CSV for q and v, in the design's order
  /// (`<body>.x`, ..., then `<body>.vx`, ...). Sizes nq and nv.
  virtual std::vector<std::string> position_names() const = 0;
  virtual std::vector<std::string> velocity_names() const = 0;
};

/// The free generalized force f = S(q) u − H(q, v) into `f` (resized), in its storage: what both
/// integrators push through M⁻¹ (H written in place where the system can, then negated).
template <typename Scalar>
void write_free_force(const LagrangianSystem<Scalar>& system,
                      const typename LagrangianSystem<Scalar>::Vector& q,
                      const typename LagrangianSystem<Scalar>::Vector& v,
                      const typename LagrangianSystem<Scalar>::Vector& u,
                      typename LagrangianSystem<Scalar>::Vector& f) {
  system.write_bias_forces(q, v, f);
  f = -f;
  if (system.num_inputs() > 0) f += system.input_matrix(q) * u;
}

}  // namespace impactbench::model
