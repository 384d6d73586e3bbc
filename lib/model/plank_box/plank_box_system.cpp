#include "lib/model/plank_box/plank_box_system.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

// Formulas: see the derivation at the top of plank_box_system.hpp.
namespace impactbench::model {
template <typename Scalar>
PlankBoxSystem<Scalar>::PlankBoxSystem(PlankBoxParameters parameters)
    : parameters_(std::move(parameters)) {
  parameters_.validate();
}

template <typename Scalar>
void PlankBoxSystem<Scalar>::fail_sizes(const Vector& q, const Vector* v) const {
  if (q.size() != 4)
    throw std::invalid_argument("PlankBoxSystem: q must have 4 entries (x, y, theta, phi), got " +
                                std::to_string(q.size()));
  throw std::invalid_argument(
      "PlankBoxSystem: v must have 4 entries (vx, vy, omega, phi_dot), got " +
      std::to_string(v->size()));
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::SparseMatrix PlankBoxSystem<Scalar>::mass_matrix(
    const Vector& q) const {
  check_sizes(q, nullptr);
  const PlankBoxParameters& p = parameters_;
  SparseMatrix M(4, 4);
  M.reserve(Eigen::VectorXi::Constant(4, 1));
  M.insert(kBoxX, kBoxX) = Scalar(p.box_mass);
  M.insert(kBoxY, kBoxY) = Scalar(p.box_mass);
  M.insert(kBoxTheta, kBoxTheta) = Scalar(p.box_inertia());
  M.insert(kPlankPhi, kPlankPhi) = Scalar(p.plank_hinge_inertia());
  M.makeCompressed();
  return M;
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::Vector PlankBoxSystem<Scalar>::bias_forces(const Vector& q,
                                                                            const Vector& v) const {
  check_sizes(q, &v);
  using std::cos;
  const PlankBoxParameters& p = parameters_;
  Vector H = Vector::Zero(4);
  H(kBoxY) = Scalar(p.box_mass * p.gravity);
  // Spring, damper and the plank's weight acting at L_P/2 from the hinge (F.5, sign corrected).
  H(kPlankPhi) = p.plank_stiffness * q(kPlankPhi) + p.plank_damping * v(kPlankPhi) +
                 p.plank_mass * p.gravity * 0.5 * p.plank_length * cos(q(kPlankPhi));
  return H;
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::SparseMatrix PlankBoxSystem<Scalar>::damping_matrix(
    const Vector& q, const Vector& v) const {
  check_sizes(q, &v);
  SparseMatrix C(4, 4);
  C.insert(kPlankPhi, kPlankPhi) = Scalar(parameters_.plank_damping);
  return C;
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::Matrix PlankBoxSystem<Scalar>::input_matrix(
    const Vector& q) const {
  check_sizes(q, nullptr);
  Matrix S = Matrix::Zero(4, 3);
  S.topRows(3).setIdentity();
  return S;
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::Vector PlankBoxSystem<Scalar>::position_rate(
    const Vector& q, const Vector& v) const {
  check_sizes(q, &v);
  return v;
}

template <typename Scalar>
typename PlankBoxSystem<Scalar>::Vector PlankBoxSystem<Scalar>::integrate_position(
    const Vector& q, const Vector& v, const Scalar& h) const {
  check_sizes(q, &v);
  return q + h * v;
}

template <typename Scalar>
Contact<Scalar> PlankBoxSystem<Scalar>::corner_contact(const Vector& q, const Vector& v,
                                                       PlankBoxCorner corner) const {
  check_sizes(q, &v);
  using std::cos;
  using std::sin;
  const PlankBoxParameters& p = parameters_;
  const double side = corner == PlankBoxCorner::kLeft ? -1.0 : 1.0;
  const double bx = side * 0.5 * p.box_length;
  const double by = -0.5 * p.box_height;

  const Scalar& x = q(kBoxX);
  const Scalar& y = q(kBoxY);
  const Scalar& theta = q(kBoxTheta);
  const Scalar& phi = q(kPlankPhi);
  const Scalar cphi = cos(phi);
  const Scalar sphi = sin(phi);
  const Scalar alpha = theta - phi;
  const Scalar calpha = cos(alpha);
  const Scalar salpha = sin(alpha);

  // Box centre and corner offset in plank axes.
  const Scalar xl = cphi * x + sphi * y;
  const Scalar yl = -sphi * x + cphi * y;
  const Scalar ax = calpha * bx - salpha * by;
  const Scalar ay = salpha * bx + calpha * by;

  Contact<Scalar> contact;
  contact.key = ContactKey{kBoxBody, kPlankBody, static_cast<int>(corner)};
  contact.name = corner == PlankBoxCorner::kLeft ? "C_L" : "C_R";
  contact.gap = yl + ay - 0.5 * p.plank_thickness;

  JacobianBlock<Scalar> block;
  block.first_velocity = 0;
  block.rows.resize(2, 4);
  block.rows(0, kBoxX) = -sphi;
  block.rows(0, kBoxY) = cphi;
  block.rows(0, kBoxTheta) = ax;
  block.rows(0, kPlankPhi) = -(xl + ax);
  block.rows(1, kBoxX) = cphi;
  block.rows(1, kBoxY) = sphi;
  block.rows(1, kBoxTheta) = -ay;
  block.rows(1, kPlankPhi) = yl + ay;
  contact.blocks.push_back(std::move(block));

  const Scalar& phi_dot = v(kPlankPhi);
  const Scalar alpha_dot = v(kBoxTheta) - phi_dot;
  const Scalar e1_pdot = cphi * v(kBoxX) + sphi * v(kBoxY);
  const Scalar e2_pdot = -sphi * v(kBoxX) + cphi * v(kBoxY);
  contact.normal_drift =
      -2.0 * phi_dot * e1_pdot - alpha_dot * alpha_dot * ay - phi_dot * phi_dot * yl;
  contact.tangent_drift.resize(1);
  contact.tangent_drift(0) =
      2.0 * phi_dot * e2_pdot - alpha_dot * alpha_dot * ax - phi_dot * phi_dot * xl;

  contact.friction = p.friction;
  contact.restitution = p.restitution;
  const double c = value_of(cphi), s = value_of(sphi);
  const double xl_c = value_of(xl + ax), yl_c = value_of(yl + ay);
  contact.point = Eigen::Vector3d(c * xl_c - s * yl_c, s * xl_c + c * yl_c, 0.0);
  contact.normal = Eigen::Vector3d(-s, c, 0.0);
  return contact;
}

template <typename Scalar>
void PlankBoxSystem<Scalar>::find_contacts(const Vector& q, const Vector& v, double margin,
                                           std::vector<Contact<Scalar>>& out) const {
  (void)margin;  // Two potential contacts: always reported.
  out.clear();
  out.push_back(corner_contact(q, v, PlankBoxCorner::kLeft));
  out.push_back(corner_contact(q, v, PlankBoxCorner::kRight));
}

template <typename Scalar>
Scalar PlankBoxSystem<Scalar>::energy(const Vector& q, const Vector& v) const {
  check_sizes(q, &v);
  using std::sin;
  const PlankBoxParameters& p = parameters_;
  const Scalar kinetic = 0.5 * p.box_mass * (v(kBoxX) * v(kBoxX) + v(kBoxY) * v(kBoxY)) +
                         0.5 * p.box_inertia() * v(kBoxTheta) * v(kBoxTheta) +
                         0.5 * p.plank_hinge_inertia() * v(kPlankPhi) * v(kPlankPhi);
  const Scalar potential = p.box_mass * p.gravity * q(kBoxY) +
                           p.plank_mass * p.gravity * 0.5 * p.plank_length * sin(q(kPlankPhi)) +
                           0.5 * p.plank_stiffness * q(kPlankPhi) * q(kPlankPhi);
  return kinetic + potential;
}

template <typename Scalar>
std::vector<std::string> PlankBoxSystem<Scalar>::position_names() const {
  return {"box.x", "box.y", "box.theta", "plank.phi"};
}

template <typename Scalar>
std::vector<std::string> PlankBoxSystem<Scalar>::velocity_names() const {
  return {"box.vx", "box.vy", "box.omega", "plank.omega"};
}

template class PlankBoxSystem<double>;
template class PlankBoxSystem<AutoDiff>;

}  // namespace impactbench::model
