#pragma once
// The plank–box model of the source's appendix F: a fully actuated box resting on a plank that
// is hinged to the world at one end and held by a torsional spring and damper. The line contact
// is modelled by the box's two bottom corners C_L and C_R (F.1).
//
// Derivation (done here from scratch; the text's typos are listed at the end)
// ===========================================================================
// Coordinates. Global (world-frame) coordinates, the text's q_g (F.1):
//     q = (x, y, θ, φ),  v = q̇ = (ẋ, ẏ, θ̇, φ̇),
// p = (x, y) the box centre in the world, θ the box angle in the world, φ the plank angle; the
// hinge is the world origin, y up. Trajectory columns: box.x, box.y, box.theta, plank.phi, then
// box.vx, box.vy, box.omega, plank.omega, all world frame. Global coordinates make M constant;
// the price is that the gaps are measured in the rotating plank frame, which is done below.
//
// Plank frame: e1 = (cos φ, sin φ) along the plank (from the hinge towards its free end),
// e2 = (−sin φ, cos φ) its upward normal. The plank's centre of mass is at (L_P/2) e1; its top
// surface is the line {s e1 + (l_P/2) e2}. Box-centre coordinates in the plank frame (the text's
// x_l, y_l of F.7):  x_l = e1ᵀp = x cos φ + y sin φ,  y_l = e2ᵀp = −x sin φ + y cos φ.
//
// Lagrangian L = T − V:
//     T = ½ m_B (ẋ² + ẏ²) + ½ J_B θ̇² + ½ J_H φ̇²,   J_H = m_P L_P²/4 + J_P   (F.4)
//     V = m_B g y + m_P g (L_P/2) sin φ + ½ k_P φ²,
// plus the damper's Rayleigh function ½ b_P φ̇² and the input's virtual work.
// Equations of motion in the project's (B.2) sign convention M v̇ + H = S u + Σ w λ:
//     M = diag(m_B, m_B, J_B, J_H)                                 (constant, F.4)
//     H = (0,  m_B g,  0,  k_P φ + b_P φ̇ + m_P g (L_P/2) cos φ)   (no Coriolis terms)
//     S = [I₃; 0 0 0]  (4×3): u = (F_x, F_y, τ) is a force on the box centre along the WORLD
//                      axes plus a torque on the box (F.6).
// energy() = T + V. With b_P = 0 and u = 0 it is conserved; in general dE/dt = vᵀS u − b_P φ̇².
//
// Gaps. Corner k ∈ {L, R} sits at body-frame b_k = (s_k L_B/2, −l_B/2), s_L = −1, s_R = +1
// (C_L is the corner on the hinge side when θ = φ). With α = θ − φ the box angle relative to the
// plank, R(·) the planar rotation, and a = R(α) b_k the corner offset in plank axes,
//     a_x = cos α b_x − sin α b_y,   a_y = sin α b_x + cos α b_y,
// the corner is at c = p + R(θ) b_k in the world and at (x_l + a_x, y_l + a_y) in the plank
// frame. The gap is its height above the top surface, and its tangential coordinate is
//     h_n = e2ᵀc − l_P/2 = y_l + a_y − l_P/2,          s_t = e1ᵀc = x_l + a_x.
// (h_n equals F.25/F.26: y_l − l_P/2 + s_k sin α L_B/2 − cos α l_B/2.)
//
// Jacobians. Using ∂e1/∂φ = e2, ∂e2/∂φ = −e1, ∂a/∂α = (−a_y, a_x), ∂α/∂θ = 1, ∂α/∂φ = −1:
//     w_n = ∂h_n/∂q = ( −sin φ,  cos φ,  a_x,  −(x_l + a_x) ),
//     W_t = ∂s_t/∂q = (  cos φ,  sin φ, −a_y,    y_l + a_y  ).
// W_tᵀv is the corner's velocity relative to the coincident plank point projected on e1 (the
// plank point at height d = e2ᵀc moves with −φ̇ d e1), i.e. sliding along the plank; the tangent
// happens to be integrable because the plank frame is a rigid body frame. Positive normal force
// λ_n pushes the box along +e2 and the plank down with torque −λ_n (x_l + a_x) (reaction at the
// contact point, lever arm along e1), as w_n shows.
//
// Drift terms, with α̇ = θ̇ − φ̇, ẋ_l = e1ᵀṗ + φ̇ y_l, ẏ_l = e2ᵀṗ − φ̇ x_l, ṗ = (ẋ, ẏ):
//     ẇ_nᵀv = −2 φ̇ e1ᵀṗ − α̇² a_y − φ̇² y_l,
//     Ẇ_tᵀv =  2 φ̇ e2ᵀṗ − α̇² a_x − φ̇² x_l,
// so that ḧ_n = w_nᵀv̇ + ẇ_nᵀv and s̈_t = W_tᵀv̇ + Ẇ_tᵀv.
//
// Where the text is wrong (checked by tests/model/plank_box_test.cpp)
//   F.3/F.5: F writes M v̇ − H = S u, so its H is a force (the negative of ours). Its spring
//            term +k_P φ is then a torque pushing away from φ = 0 (the damper −b_P φ̇ is right):
//            restoring is −k_P φ − b_P φ̇ as a force, +k_P φ + b_P φ̇ in our H. F.10 repeats the
//            spring sign; apart from it F.9–F.11 are right (test LocalEquationsOfMotion...).
//   F.23/F.24: x-components of the corners. Correct: C_R x = x_l + cos α L_B/2 + sin α l_B/2,
//            C_L x = x_l − cos α L_B/2 + sin α l_B/2 (F.23 has −sin, F.24 has +cos).
//            F.30/F.31/F.33 inherit them in the tangential (x) rows: correct are
//            C_L: ẋ_l + α̇ (sin α L_B/2 + cos α l_B/2),  C_R: ẋ_l + α̇ (−sin α L_B/2 + cos α l_B/2).
//   F.35:    the first two columns of W_Tᵀ are swapped; in the text's local coordinates the row
//            is (1, 0, −a_y, 0), with the third entries just given (F.35 inherits F.33's signs).
//   F.25:    writes "− l_p" for the surface offset; it is l_P/2 (as its right-hand side says).
// The text's input matrix S_l (F.11) is the world-frame force (F_x, F_y) and torque pulled
// back through F.7 (S_l = (∂q_g/∂q_l)ᵀ S_g), so F's input is world frame, as here.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lib/model/autodiff.hpp"
#include "lib/model/lagrangian_system.hpp"
#include "lib/model/plank_box/plank_box_parameters.hpp"

namespace impactbench::model {

/// Which bottom corner of the box: C_L at body-frame (−L_B/2, −l_B/2), C_R at (+L_B/2, −l_B/2).
enum class PlankBoxCorner { kLeft = 0, kRight = 1 };

template <typename Scalar>
class PlankBoxSystem final : public LagrangianSystem<Scalar> {
 public:
  using typename LagrangianSystem<Scalar>::Vector;
  using typename LagrangianSystem<Scalar>::Matrix;
  using typename LagrangianSystem<Scalar>::SparseMatrix;

  /// Indices into q and v.
  static constexpr int kBoxX = 0, kBoxY = 1, kBoxTheta = 2, kPlankPhi = 3;
  /// Body ids in ContactKey.
  static constexpr int kBoxBody = 0, kPlankBody = 1;

  /// Throws std::invalid_argument naming the offending field (PlankBoxParameters::validate).
  explicit PlankBoxSystem(PlankBoxParameters parameters = {});

  const PlankBoxParameters& parameters() const { return parameters_; }

  int num_positions() const override { return 4; }
  int num_velocities() const override { return 4; }
  int num_inputs() const override { return 3; }
  int tangent_dim() const override { return 1; }

  SparseMatrix mass_matrix(const Vector& q) const override;
  Vector bias_forces(const Vector& q, const Vector& v) const override;
  /// The hinge damper: ∂H/∂v = diag(0, 0, 0, b_P).
  bool has_damping_matrix() const override { return true; }
  SparseMatrix damping_matrix(const Vector& q, const Vector& v) const override;
  Matrix input_matrix(const Vector& q) const override;
  Vector position_rate(const Vector& q, const Vector& v) const override;
  Vector integrate_position(const Vector& q, const Vector& v, const Scalar& h) const override;

  /// Always both corners, C_L then C_R, whatever `margin` (a two-contact system).
  void find_contacts(const Vector& q, const Vector& v, double margin,
                     std::vector<Contact<Scalar>>& out) const override;
  /// One corner's contact: gap, [w_nᵀ; W_tᵀ] as a single 2×4 block, drifts, world point/normal.
  Contact<Scalar> corner_contact(const Vector& q, const Vector& v, PlankBoxCorner corner) const;

  Scalar energy(const Vector& q, const Vector& v) const override;

  std::vector<std::string> position_names() const override;
  std::vector<std::string> velocity_names() const override;

 private:
  // Inline, as it runs on every call of the hot paths; the message is built out of line.
  void check_sizes(const Vector& q, const Vector* v) const {
    if (q.size() != num_positions() || (v != nullptr && v->size() != num_velocities())) [[unlikely]]
      fail_sizes(q, v);
  }
  [[noreturn]] void fail_sizes(const Vector& q, const Vector* v) const;

  PlankBoxParameters parameters_;
};

extern template class PlankBoxSystem<double>;
extern template class PlankBoxSystem<AutoDiff>;

}  // namespace impactbench::model
