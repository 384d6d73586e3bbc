#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/model/slip_direction.hpp"
#include "lib/output/number_text.hpp"
#include "lib/sensitivity/derivative_size.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <algorithm>

#include <Eigen/Cholesky>
#include <Eigen/LU>

// Formulas: see the header (B.36–B.41 flow, B.19–B.24 impact with restitution).
namespace impactbench::sensitivity {
namespace {

/// find_contacts margin [m] that lists every potential contact of a small system (the
/// event-driven engine's default too; the planar system rejects an infinite margin).
constexpr double kAllContactsMargin = 1e3;

template <typename Scalar>
using Vec = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
template <typename Scalar>
using Mat = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

double value_of(double x) {
  return x;
}
double value_of(const AutoDiff& x) {
  return x.value();
}
/// How the model makes its scalars in one evaluation: every constant and every value the system
/// returns carries derivatives of one size (derivative_size.hpp), and the contact material is
/// the contacts' own μ and e or (parameter states) the state's last two entries, so that their
/// derivatives are the parameter gains.
template <typename Scalar>
struct ScalarContext : DerivativeSize<Scalar> {
  using DerivativeSize<Scalar>::DerivativeSize;
  bool from_state = false;
  Scalar mu{0}, e{0};
  Scalar friction(const model::Contact<Scalar>& c) const {
    return from_state ? mu : this->constant(c.friction);
  }
  Scalar restitution(const model::Contact<Scalar>& c) const {
    return from_state ? e : this->constant(c.restitution);
  }
};

/// The model indexes contacts by position in this list, so it must have the same length at
/// every state; systems whose contact features come and go (box on box) are refused here.
void require_contact_count(std::size_t found, std::size_t expected) {
  if (found != expected)
    throw std::runtime_error(
        "sensitivity: the system lists " + std::to_string(found) + " potential contacts here and " +
        std::to_string(expected) +
        " elsewhere; the linearisation needs a fixed contact set, which contacts between "
        "polygons (box on box) do not give");
}

/// The contacts at (q, v), lifted to the context's derivative size.
template <typename Scalar>
std::vector<model::Contact<Scalar>> contacts_of(const model::LagrangianSystem<Scalar>& system,
                                                const Vec<Scalar>& q, const Vec<Scalar>& v,
                                                std::size_t expected,
                                                const DerivativeSize<Scalar>& ad) {
  std::vector<model::Contact<Scalar>> out;
  system.find_contacts(q, v, kAllContactsMargin, out);
  require_contact_count(out.size(), expected);
  for (auto& c : out) c = ad.lift(std::move(c));
  return out;
}

/// w_n, W_t and ζ = [w_n W_t]ᵀ v of a lifted contact, lifted (entries no block touches are
/// constant zeros).
template <typename Scalar>
Vec<Scalar> normal_of(const model::Contact<Scalar>& c, int nv, const DerivativeSize<Scalar>& ad) {
  return ad.lift(c.normal_direction(nv));
}
template <typename Scalar>
Mat<Scalar> tangents_of(const model::Contact<Scalar>& c, int nv, const DerivativeSize<Scalar>& ad) {
  return ad.lift(c.tangent_directions(nv));
}
template <typename Scalar>
Vec<Scalar> relative_velocity_of(const model::Contact<Scalar>& c, const Vec<Scalar>& v,
                                 const DerivativeSize<Scalar>& ad) {
  return ad.lift(c.relative_velocity(v));
}

/// The slip direction of a closed contact in `mode`: planar s = ±1 of the phase; spatial
/// ε(ζ_t): the engine's slip direction (lib/model/slip_direction.hpp) with its default velocity
/// tolerance as blend speed, oriented along the phase's reference s_ref (hybrid_mode.hpp); the
/// plane's ±1. Without a reference (none was recorded) Coulomb's ζ_t/‖ζ_t‖ where ζ_t is clear of
/// that speed. Frictionless contacts never call this.
template <typename Scalar>
Vec<Scalar> slip_direction_vector(const HybridMode& mode, int i, const Vec<Scalar>& zeta_t,
                                  const DerivativeSize<Scalar>& ad) {
  if (zeta_t.size() == 1) return ad.vector({static_cast<double>(slip_direction(mode[i]))});
  const std::vector<double>& ref = mode.reference(i);
  const double blend_speed = engines::event_driven::EventDrivenOptions{}.velocity_tolerance;
  if (ref.size() == static_cast<std::size_t>(zeta_t.size()))
    return model::smoothed_slip_direction<Scalar>(zeta_t, ad.vector(ref), blend_speed);
  const Scalar norm_squared = zeta_t.squaredNorm();
  if (!(value_of(norm_squared) >= blend_speed * blend_speed))
    throw std::invalid_argument("MechanicalHybridModel: contact " + std::to_string(i) +
                                " slips with no reference direction and a sliding speed below " +
                                output::number_text(blend_speed) + " m/s");
  using std::sqrt;
  return zeta_t / Scalar(sqrt(norm_squared));
}

/// Rows J, columns C, drifts d of the closed contacts (header comment), and where each
/// contact's normal / first tangential multiplier sits (−1: none). Spatial slip directions turn
/// with ζ_t = W_tᵀ v, hence v.
template <typename Scalar>
struct ConstraintSet {
  Mat<Scalar> J, C;
  Vec<Scalar> drift;
  std::vector<int> normal_row, tangent_row;
  std::vector<Vec<Scalar>> slip;  ///< per contact: its slip direction (slipping, μ > 0)
};

template <typename Scalar>
ConstraintSet<Scalar> closed_constraints(const HybridMode& mode,
                                         const std::vector<model::Contact<Scalar>>& contacts,
                                         const Vec<Scalar>& v, int nv,
                                         const ScalarContext<Scalar>& context) {
  const int nc = static_cast<int>(contacts.size());
  int k = 0;
  for (int i = 0; i < nc; ++i)
    k += mode[i] == ContactPhase::kStick ? 1 + contacts[i].tangent_dim()
                                         : (is_closed(mode[i]) ? 1 : 0);
  ConstraintSet<Scalar> set;
  set.J = context.zeros(k, nv);
  set.C = context.zeros(nv, k);
  set.drift = context.zeros(k);
  set.normal_row.assign(nc, -1);
  set.tangent_row.assign(nc, -1);
  set.slip.resize(nc);
  int row = 0;
  for (int i = 0; i < nc; ++i) {
    if (!is_closed(mode[i])) continue;
    const auto& c = contacts[i];
    const int d = c.tangent_dim();
    const Vec<Scalar> wn = normal_of(c, nv, context);
    set.normal_row[i] = row;
    set.J.row(row) = wn.transpose();
    set.drift(row) = c.normal_drift;
    if (d == 1) {
      const Vec<Scalar> wt = tangents_of(c, nv, context).col(0);
      if (mode[i] == ContactPhase::kStick) {
        set.C.col(row) = wn;
        ++row;
        set.tangent_row[i] = row;
        set.J.row(row) = wt.transpose();
        set.C.col(row) = wt;
        set.drift(row) = c.tangent_drift(0);
      } else {
        // Slip friction folded into the normal column: λ_t = −μ λ_n s.
        set.C.col(row) = wn - Scalar(context.friction(c) * double(slip_direction(mode[i]))) * wt;
      }
      ++row;
      continue;
    }
    const Mat<Scalar> Wt = tangents_of(c, nv, context);
    if (mode[i] == ContactPhase::kStick) {
      set.C.col(row) = wn;
      set.tangent_row[i] = row + 1;
      set.J.middleRows(row + 1, d) = Wt.transpose();
      set.C.middleCols(row + 1, d) = Wt;
      set.drift.segment(row + 1, d) = c.tangent_drift;
      row += 1 + d;
    } else if (value_of(context.friction(c)) > 0.0) {
      set.slip[i] =
          slip_direction_vector<Scalar>(mode, i, Vec<Scalar>(Wt.transpose() * v), context);
      // The friction vector is evaluated before the product: Eigen's matrix-vector product
      // would pull μ out as a scalar factor and combine it with its own constants.
      const Vec<Scalar> friction_direction = context.friction(c) * set.slip[i];
      set.C.col(row) = wn - Wt * friction_direction;
      ++row;
    } else {
      set.C.col(row) = wn;
      ++row;
    }
  }
  return set;
}

/// X = A⁻¹ B by Gaussian elimination with partial pivoting on the values. Written out because
/// Eigen's triangular solves skip right-hand-side entries whose value is exactly zero, which
/// drops the derivatives of an AutoDiff right-hand side (e.g. ∂v̇/∂u at u = 0).
template <typename Scalar>
Mat<Scalar> solve_dense(Mat<Scalar> A, Mat<Scalar> B, const char* what) {
  const Eigen::Index n = A.rows();
  double scale = 0.0;
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) scale = std::max(scale, std::abs(value_of(A(i, j))));
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index pivot = k;
    for (Eigen::Index i = k + 1; i < n; ++i)
      if (std::abs(value_of(A(i, k))) > std::abs(value_of(A(pivot, k)))) pivot = i;
    if (!(std::abs(value_of(A(pivot, k))) > 1e-13 * scale))
      throw std::runtime_error(std::string("MechanicalHybridModel: ") + what +
                               " is singular (redundant closed contacts in the mode?)");
    A.row(k).swap(A.row(pivot));
    B.row(k).swap(B.row(pivot));
    for (Eigen::Index i = k + 1; i < n; ++i) {
      const Scalar factor = A(i, k) / A(k, k);
      A.row(i) -= factor * A.row(k);
      B.row(i) -= factor * B.row(k);
    }
  }
  for (Eigen::Index k = n - 1; k >= 0; --k) {
    for (Eigen::Index i = k + 1; i < n; ++i) B.row(k) -= A(k, i) * B.row(i);
    B.row(k) /= A(k, k);
  }
  return B;
}

/// A maximal set of linearly independent rows of A (on the values), by Gram–Schmidt with
/// pivoting on the largest remaining row; rows whose remainder is below 1e-9 × the largest row
/// norm count as dependent. The choice is made on values only, so the AD derivatives below are
/// those of the solve restricted to these rows.
template <typename Scalar>
std::vector<Eigen::Index> independent_rows(const Mat<Scalar>& A) {
  Eigen::MatrixXd rest(A.rows(), A.cols());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) rest(i, j) = value_of(A(i, j));
  const double scale = rest.rowwise().norm().maxCoeff();
  std::vector<Eigen::Index> chosen;
  std::vector<bool> used(static_cast<std::size_t>(A.rows()), false);
  while (static_cast<Eigen::Index>(chosen.size()) < A.rows()) {
    Eigen::Index best = -1;
    double best_norm = 0.0;
    for (Eigen::Index i = 0; i < rest.rows(); ++i) {
      if (used[static_cast<std::size_t>(i)]) continue;
      const double norm = rest.row(i).norm();
      if (best < 0 || norm > best_norm) {
        best = i;
        best_norm = norm;
      }
    }
    if (!(best_norm > 1e-9 * scale)) break;
    used[static_cast<std::size_t>(best)] = true;
    chosen.push_back(best);
    const Eigen::RowVectorXd unit = rest.row(best) / best_norm;
    for (Eigen::Index i = 0; i < rest.rows(); ++i)
      if (!used[static_cast<std::size_t>(i)]) rest.row(i) -= rest.row(i).dot(unit) * unit;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

/// Multipliers λ with D λ = r. D invertible: the unique solution. D singular (redundant closed
/// contacts, e.g. the two sticking bottom corners of a box on a line, whose tangent rows are
/// equal): the consistent system's solutions form an affine set, D_R λ = r_R over independent
/// rows R, and λ is the one of least weighted norm Σ λ_j² / w_j,
///     λ = W D_Rᵀ (D_R W D_Rᵀ)⁻¹ r_R,   W = diag(w)   (w empty: W = I).
/// The accelerations M⁻¹(F + C λ) do not depend on the choice; the split of the forces among
/// redundant contacts does. Throws when D is singular and the system inconsistent.
template <typename Scalar>
Vec<Scalar> constraint_multipliers(const Mat<Scalar>& D, const Vec<Scalar>& r, const Vec<Scalar>& w,
                                   const DerivativeSize<Scalar>& ad, const char* what) {
  const std::vector<Eigen::Index> rows = independent_rows(D);
  const Eigen::Index k = D.rows();
  if (static_cast<Eigen::Index>(rows.size()) == k) return solve_dense<Scalar>(D, r, what);
  if (rows.empty()) return ad.zeros(k);
  const Eigen::Index rank = static_cast<Eigen::Index>(rows.size());
  Mat<Scalar> DR(rank, k);
  Vec<Scalar> rR(rank);
  for (Eigen::Index i = 0; i < rank; ++i) {
    DR.row(i) = D.row(rows[static_cast<std::size_t>(i)]);
    rR(i) = r(rows[static_cast<std::size_t>(i)]);
  }
  Mat<Scalar> WDt = DR.transpose();
  if (w.size() == k)
    for (Eigen::Index j = 0; j < k; ++j) WDt.row(j) *= w(j);
  const Mat<Scalar> normal = DR * WDt;
  const Vec<Scalar> lambda = WDt * solve_dense<Scalar>(normal, Mat<Scalar>(rR), what).col(0);
  // The dropped rows must hold too (they do when the redundancy is geometric).
  double residual = 0.0, size = 0.0;
  const Vec<Scalar> Dl = D * lambda;
  for (Eigen::Index i = 0; i < k; ++i) {
    residual = std::max(residual, std::abs(value_of(Dl(i)) - value_of(r(i))));
    size = std::max(size, std::abs(value_of(r(i))));
  }
  if (!(residual <= 1e-8 * std::max(size, 1.0)))
    throw std::runtime_error(std::string("MechanicalHybridModel: ") + what +
                             " is singular and the constraints are inconsistent (residual " +
                             output::number_text(residual) + ")");
  return lambda;
}

template <typename Scalar>
struct FlowResult {
  Vec<Scalar> q_dot, v_dot, lambda_n;
  Mat<Scalar> lambda_t;  ///< num_contacts × d
};

template <typename Scalar>
FlowResult<Scalar> mode_flow(const model::LagrangianSystem<Scalar>& system, const HybridMode& mode,
                             const Vec<Scalar>& q, const Vec<Scalar>& v, const Vec<Scalar>& u,
                             const ScalarContext<Scalar>& context) {
  const int nv = system.num_velocities();
  const auto contacts = contacts_of(system, q, v, mode.size(), context);
  const Mat<Scalar> M = context.lift(Mat<Scalar>(system.mass_matrix(q)));
  Vec<Scalar> force = -context.lift(system.bias_forces(q, v));
  if (system.num_inputs() > 0) force += context.lift(system.input_matrix(q)) * u;
  const ConstraintSet<Scalar> set = closed_constraints(mode, contacts, v, nv, context);
  // One elimination for M⁻¹ [force, C].
  Mat<Scalar> rhs_columns(nv, 1 + set.C.cols());
  rhs_columns << force, set.C;
  const Mat<Scalar> solved = solve_dense<Scalar>(M, rhs_columns, "the mass matrix");

  FlowResult<Scalar> out;
  out.q_dot = context.lift(system.position_rate(q, v));
  out.v_dot = solved.col(0);
  const int nc = static_cast<int>(contacts.size());
  const int d = system.tangent_dim();
  out.lambda_n = context.zeros(nc);
  out.lambda_t = context.zeros(nc, d);
  if (set.J.rows() == 0) return out;

  const Mat<Scalar> m_inv_c = solved.rightCols(set.C.cols());
  const Mat<Scalar> delassus = set.J * m_inv_c;
  const Vec<Scalar> rhs = -set.drift - set.J * out.v_dot;
  const char* what = "the constraint matrix J M^-1 C of the flow";
  Vec<Scalar> weights;  // empty: plain least norm
  Vec<Scalar> lambda = constraint_multipliers<Scalar>(delassus, rhs, weights, context, what);
  if (independent_rows(delassus).size() < static_cast<std::size_t>(delassus.rows())) {
    // Redundant sticking contacts: split their tangential forces in proportion to their normal
    // forces (weights w = λ_n on the tangential entries), so that all contacts of a redundant
    // group reach their cones together, exactly when the total force leaves the total cone
    // (|Σλ_t| = μ Σλ_n): the rigid body's slip condition. λ_n itself is determined.
    weights = Vec<Scalar>::Constant(delassus.rows(), context.constant(1.0));
    double largest = 0.0;
    for (int i = 0; i < nc; ++i)
      if (set.normal_row[i] >= 0)
        largest = std::max(largest, std::abs(value_of(lambda(set.normal_row[i]))));
    const double floor = std::max(1e-9 * largest, std::numeric_limits<double>::min());
    bool any = false;
    for (int i = 0; i < nc; ++i) {
      if (set.tangent_row[i] < 0) continue;
      const Scalar ln = lambda(set.normal_row[i]);
      for (int k = 0; k < d; ++k)
        weights(set.tangent_row[i] + k) = value_of(ln) > floor ? ln : context.constant(floor);
      any = true;
    }
    if (any)
      lambda = constraint_multipliers<Scalar>(delassus, rhs, weights, context, what);
    else
      weights.resize(0);
  }
  out.v_dot += m_inv_c * lambda;
  // One step of iterative refinement on the constraint residual J v̇ + d: a body held by its
  // contacts (v̇ = 0 as the difference of gravity and contact forces) would otherwise drift by
  // the round-off of that difference, ~1e-15 m/s², which sets the noise floor of the ε-tests.
  const Vec<Scalar> residual = -set.drift - set.J * out.v_dot;
  const Vec<Scalar> correction =
      constraint_multipliers<Scalar>(delassus, residual, weights, context, what);
  lambda += correction;
  out.v_dot += m_inv_c * correction;
  for (int i = 0; i < nc; ++i) {
    if (set.normal_row[i] < 0) continue;
    out.lambda_n(i) = lambda(set.normal_row[i]);
    if (d == 1) {
      // Slip: λ_t = −μ λ_n s.
      out.lambda_t(i) = set.tangent_row[i] >= 0
                            ? Scalar(lambda(set.tangent_row[i]))
                            : Scalar(context.friction(contacts[i]) * lambda(set.normal_row[i]) *
                                     double(-slip_direction(mode[i])));
    } else if (set.tangent_row[i] >= 0) {
      out.lambda_t.row(i) = lambda.segment(set.tangent_row[i], d).transpose();
    } else if (set.slip[i].size() == d) {
      out.lambda_t.row(i) =
          (-context.friction(contacts[i]) * lambda(set.normal_row[i]) * set.slip[i]).transpose();
    }
  }
  return out;
}

/// (cos φ, sin φ): the spatial slip direction of an impact impulse by its angle.
template <typename Scalar>
Vec<Scalar> direction_of_angle(const Scalar& phi) {
  using std::cos;
  using std::sin;
  Vec<Scalar> s(2);
  s << cos(phi), sin(phi);
  return s;
}

/// The angle φ* of the spatial slip impulse Λ_t = −μ Λ_n s(φ): the impulse-level Coulomb law
/// wants s along the post-impact sliding velocity, g(φ) = s(φ)^⊥ · ζ_t⁺(φ) = 0 with
/// s · ζ_t⁺ > 0. Newton's method on the values (derivative by a central difference) from the
/// pre-impact sliding direction; g also vanishes where s opposes ζ_t⁺, and Newton from there
/// may converge to such a root, so it starts again from seven more angles, π/4 apart, until a
/// root with s · ζ_t⁺ > 0 is found. Then one Newton step in Scalar from that φ*, whose
/// derivatives are those of the implicit function, dφ/dp = −(∂g/∂p)/(∂g/∂φ), because g(φ*) = 0.
template <typename Scalar, typename TangentVelocity>
Scalar coulomb_slip_angle(const TangentVelocity& zeta_t_after, const Vec<Scalar>& zeta_t_before,
                          const DerivativeSize<Scalar>& ad, int contact) {
  const auto g = [&](const Scalar& phi) {
    const Vec<Scalar> zt = zeta_t_after(direction_of_angle<Scalar>(phi));
    using std::cos;
    using std::sin;
    return Scalar(-sin(phi) * zt(0) + cos(phi) * zt(1));
  };
  const auto value = [&](double phi) { return value_of(g(ad.constant(phi))); };
  const double scale = 1.0 + std::hypot(value_of(zeta_t_before(0)), value_of(zeta_t_before(1)));
  const double h = 1e-7;
  const auto slope_at = [&](double phi) { return (value(phi + h) - value(phi - h)) / (2 * h); };
  // Newton from phi; true when it ends at a root where s(φ) slides along ζ_t⁺.
  const auto newton = [&](double& phi) {
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double slope = slope_at(phi);
      const double residual = value(phi);
      if (!(std::abs(slope) > 1e-12 * scale)) return false;
      phi -= residual / slope;
      if (std::abs(residual) <= 1e-15 * scale) break;
    }
    const Vec<Scalar> zt = zeta_t_after(direction_of_angle<Scalar>(ad.constant(phi)));
    return std::cos(phi) * value_of(zt(0)) + std::sin(phi) * value_of(zt(1)) > 0.0 &&
           std::abs(value(phi)) <= 1e-9 * scale && std::abs(slope_at(phi)) > 1e-12 * scale;
  };
  const double start = std::atan2(value_of(zeta_t_before(1)), value_of(zeta_t_before(0)));
  for (int k = 0; k < 8; ++k) {
    double phi = start + k * std::numbers::pi / 4;
    if (newton(phi)) return ad.constant(phi) - Scalar(g(ad.constant(phi)) / slope_at(phi));
  }
  throw std::runtime_error("MechanicalHybridModel: no slip impulse at contact " +
                           std::to_string(contact) +
                           " opposes the post-impact sliding (the impact sticks, or grazes the "
                           "stick cone: Γ = 0)");
}

/// A contact that stays closed through an impact must push: a negative normal impulse at a
/// contact other than the impacting one means the engine's impulse-level problem (Λ_n ≥ 0)
/// lifts that contact off instead, a phase change this reset does not carry. Inside a macro
/// event this is the order dependence of sequential impacts (contact j landed first, the later
/// impact lifts it off again: the post-event state differs by order, no jump gain exists).
template <typename Scalar>
void refuse_pulling_contacts(const Vec<Scalar>& impulse, const std::vector<int>& normal_row,
                             int impacting) {
  double largest = 0.0;
  for (Eigen::Index k = 0; k < impulse.size(); ++k)
    largest = std::max(largest, std::abs(value_of(impulse(k))));
  for (int j = 0; j < static_cast<int>(normal_row.size()); ++j) {
    if (j == impacting || normal_row[j] < 0) continue;
    const double impulse_n = value_of(impulse(normal_row[j]));
    if (impulse_n < -1e-9 * largest)
      throw std::runtime_error(
          "MechanicalHybridModel: the impact of contact " + std::to_string(impacting) +
          " pulls on closed contact " + std::to_string(j) + " (normal impulse " +
          output::number_text(impulse_n) +
          " N s): the engine lifts it off, so simultaneous impacts here end differently in "
          "different orders and have no jump gain");
  }
}

template <typename Scalar>
Vec<Scalar> post_impact_velocity(const model::LagrangianSystem<Scalar>& system,
                                 const HybridMode& mode, const MicroEvent& event,
                                 const Vec<Scalar>& q, const Vec<Scalar>& v,
                                 const ScalarContext<Scalar>& context) {
  const int nv = system.num_velocities();
  const auto contacts = contacts_of(system, q, v, mode.size(), context);
  const HybridMode after = apply_event(mode, event);
  const auto& impacting = contacts[event.contact];
  const Scalar restitution = context.restitution(impacting);
  const Scalar mu = context.friction(impacting);
  const double e = value_of(restitution);
  const int d = impacting.tangent_dim();
  if (is_closed(event.phase_after) && e > 0.0)
    throw std::invalid_argument(
        "MechanicalHybridModel: an impact with restitution e = " + output::number_text(e) +
        " cannot leave contact " + std::to_string(event.contact) + " closed");
  ConstraintSet<Scalar> set = closed_constraints(after, contacts, v, nv, context);
  const Vec<Scalar> zeta = relative_velocity_of(impacting, v, context);
  // Spatial slip impulse of the impacting contact: its direction is solved (Coulomb law).
  bool coulomb_slip = d > 1 && value_of(mu) > 0.0 && is_closed(event.phase_after) &&
                      event.phase_after != ContactPhase::kStick;
  if (!is_closed(event.phase_after)) {
    // Bounce: the impacting contact's normal row; its friction as tangential rows with target
    // ζ_t⁺ = 0 (stick impulse), or folded into the normal column along s (slip impulse; planar
    // s from ζ_t⁻ unless given, spatial s solved; zero friction if μ = 0 or no tangential
    // velocity).
    const Vec<Scalar> wn = normal_of(impacting, nv, context);
    const bool stick = event.bounce_impulse == ContactPhase::kStick && value_of(mu) > 0.0;
    const Eigen::Index row = set.J.rows();
    const Eigen::Index added = stick ? 1 + d : 1;
    set.J.conservativeResize(row + added, Eigen::NoChange);
    set.C.conservativeResize(Eigen::NoChange, row + added);
    set.J.row(row) = wn.transpose();
    set.normal_row[event.contact] = static_cast<int>(row);
    if (stick) {
      const Mat<Scalar> Wt = tangents_of(impacting, nv, context);
      set.C.col(row) = wn;
      set.J.middleRows(row + 1, d) = Wt.transpose();
      set.C.middleCols(row + 1, d) = Wt;
      set.tangent_row[event.contact] = static_cast<int>(row + 1);
    } else if (d == 1) {
      const Vec<Scalar> wt = tangents_of(impacting, nv, context).col(0);
      const double zt = value_of(zeta(1));
      const int given = slip_direction(event.bounce_impulse);
      const double s = given != 0 ? given : (zt > 0.0 ? 1.0 : (zt < 0.0 ? -1.0 : 0.0));
      set.C.col(row) = wn - Scalar(mu * s) * wt;
    } else {
      set.C.col(row) = wn;
      coulomb_slip = value_of(mu) > 0.0 && value_of(zeta.tail(d).squaredNorm()) != 0.0;
    }
  }
  if (d > 1)
    for (int i = 0; i < static_cast<int>(after.size()); ++i)
      if (i != event.contact && set.slip[i].size() > 0)
        throw std::invalid_argument(
            "MechanicalHybridModel: spatial impacts while another contact slips with friction "
            "are not linearised (contact " +
            std::to_string(i) + ")");
  Vec<Scalar> target = context.zeros(set.J.rows());
  target(set.normal_row[event.contact]) = -restitution * zeta(0);

  const Mat<Scalar> M = context.lift(Mat<Scalar>(system.mass_matrix(q)));
  // The post-impact velocity; the impulse of the answer (`answer`), not of a trial slip
  // direction, must not pull on a closed contact.
  const auto velocity_after = [&](const ConstraintSet<Scalar>& with, bool answer) {
    const Mat<Scalar> m_inv_c = solve_dense<Scalar>(M, with.C, "the mass matrix");
    const Mat<Scalar> delassus = with.J * m_inv_c;
    const Vec<Scalar> impulse =
        constraint_multipliers<Scalar>(delassus, Vec<Scalar>(target - with.J * v), Vec<Scalar>(),
                                       context, "the impulse matrix J M^-1 C of the impact");
    if (answer) refuse_pulling_contacts<Scalar>(impulse, with.normal_row, event.contact);
    return Vec<Scalar>(v + m_inv_c * impulse);
  };
  if (!coulomb_slip) return velocity_after(set, true);
  const Vec<Scalar> wn = normal_of(impacting, nv, context);
  const Mat<Scalar> Wt = tangents_of(impacting, nv, context);
  const auto with_direction = [&](const Vec<Scalar>& s, bool answer) {
    ConstraintSet<Scalar> trial = set;
    const Vec<Scalar> friction_direction = mu * s;  // evaluated first, as in closed_constraints
    trial.C.col(set.normal_row[event.contact]) = wn - Wt * friction_direction;
    return velocity_after(trial, answer);
  };
  const auto zeta_t_after = [&](const Vec<Scalar>& s) {
    return Vec<Scalar>(Wt.transpose() * with_direction(s, false));
  };
  const Scalar phi =
      coulomb_slip_angle<Scalar>(zeta_t_after, Vec<Scalar>(zeta.tail(d)), context, event.contact);
  return with_direction(direction_of_angle<Scalar>(phi), true);
}

template <typename Scalar>
Scalar guard_of(const model::LagrangianSystem<Scalar>& system, const HybridMode& mode,
                const MicroEvent& event, const Vec<Scalar>& q, const Vec<Scalar>& v,
                const Vec<Scalar>& u, const ScalarContext<Scalar>& context) {
  const ContactPhase phase = mode[event.contact];
  const auto wrong = [&](const char* needed) {
    return std::invalid_argument(
        "MechanicalHybridModel: guard " + std::string(to_string(event.kind)) + " needs contact " +
        std::to_string(event.contact) + " " + needed + ", it is " + std::string(to_string(phase)));
  };
  switch (event.kind) {
    case GuardKind::kImpact: {
      if (is_closed(phase)) throw wrong("open");
      return contacts_of(system, q, v, mode.size(), context)[event.contact].gap;
    }
    case GuardKind::kSlipToStick: {
      if (slip_direction(phase) == 0) throw wrong("slipping");
      const Vec<Scalar> zeta = relative_velocity_of(
          contacts_of(system, q, v, mode.size(), context)[event.contact], v, context);
      if (zeta.size() == 2) return Scalar(zeta(1) * double(slip_direction(phase)));
      // Spatial: the sliding velocity along the slip reference (the engine's guard).
      const std::vector<double>& ref = mode.reference(event.contact);
      if (ref.size() + 1 != static_cast<std::size_t>(zeta.size()))
        throw std::invalid_argument("MechanicalHybridModel: the slip-to-stick guard of contact " +
                                    std::to_string(event.contact) +
                                    " needs the slip reference direction");
      return context.vector(ref).dot(zeta.tail(ref.size()));
    }
    case GuardKind::kLiftOff: {
      if (!is_closed(phase)) throw wrong("closed");
      return mode_flow(system, mode, q, v, u, context).lambda_n(event.contact);
    }
    case GuardKind::kStickToSlip: {
      if (phase != ContactPhase::kStick) throw wrong("sticking");
      const int s = slip_direction(event.phase_after);
      if (s == 0)
        throw std::invalid_argument(
            "MechanicalHybridModel: a stick-to-slip event must lead to slip+ or slip-");
      const auto forces = mode_flow(system, mode, q, v, u, context);
      const Scalar mu =
          context.friction(contacts_of(system, q, v, mode.size(), context)[event.contact]);
      if (forces.lambda_t.cols() == 1)
        return mu * forces.lambda_n(event.contact) +
               Scalar(forces.lambda_t(event.contact) * double(s));
      // Spatial: μ λ_n − ‖λ_t‖ (the engine's μ²λ_n² − ‖λ_t‖² has the same zero and crossing
      // direction, hence the same gains; this one is smooth where λ_t ≠ 0).
      using std::sqrt;
      return mu * forces.lambda_n(event.contact) -
             sqrt(Vec<Scalar>(forces.lambda_t.row(event.contact).transpose()).squaredNorm());
    }
  }
  throw std::logic_error("MechanicalHybridModel: unknown guard kind");
}

/// AD variables for x = (q, v[, μ, e]) and u seeded with the identity over n + m directions.
struct Seeded {
  Vec<AutoDiff> q, v, u;
  ScalarContext<AutoDiff> context;
};
Seeded seed(const Eigen::VectorXd& x, const Eigen::VectorXd& u, int nq, int nv) {
  const int total = static_cast<int>(x.size() + u.size());
  Seeded s{{}, {}, {}, ScalarContext<AutoDiff>(total)};
  s.q.resize(nq);
  s.v.resize(nv);
  s.u.resize(u.size());
  for (int i = 0; i < x.size(); ++i) {
    const AutoDiff var(x(i), total, i);
    if (i < nq)
      s.q(i) = var;
    else if (i < nq + nv)
      s.v(i - nq) = var;
    else if (i == nq + nv)
      s.context.mu = var;
    else
      s.context.e = var;
  }
  s.context.from_state = x.size() > nq + nv;
  for (int j = 0; j < u.size(); ++j) s.u(j) = AutoDiff(u(j), total, static_cast<int>(x.size()) + j);
  return s;
}

/// d(output)/d(seeded variables), `total` columns (an output without derivatives is constant).
Eigen::RowVectorXd gradient_of(const AutoDiff& y, int total) {
  return DerivativeSize<AutoDiff>(total).lift(y).derivatives().transpose();
}

}  // namespace

MechanicalHybridModel::MechanicalHybridModel(const model::LagrangianSystem<double>& system,
                                             const model::LagrangianSystem<AutoDiff>& system_ad,
                                             bool parameter_states)
    : system_(system), system_ad_(system_ad) {
  if (system.tangent_dim() != 1 && system.tangent_dim() != 2)
    throw std::invalid_argument("MechanicalHybridModel: contacts with " +
                                std::to_string(system.tangent_dim()) +
                                " tangent directions (1 planar or 2 spatial expected)");
  if (system.num_positions() != system_ad.num_positions() ||
      system.num_velocities() != system_ad.num_velocities() ||
      system.num_inputs() != system_ad.num_inputs())
    throw std::invalid_argument("MechanicalHybridModel: the double and AD systems differ in size");
  nq_ = system.num_positions();
  nv_ = system.num_velocities();
  nu_ = system.num_inputs();
  std::vector<model::Contact<double>> contacts;
  system.find_contacts(Eigen::VectorXd::Zero(nq_), Eigen::VectorXd::Zero(nv_), kAllContactsMargin,
                       contacts);
  num_contacts_ = static_cast<int>(contacts.size());
  if (parameter_states) {
    if (contacts.empty())
      throw std::invalid_argument("MechanicalHybridModel: parameter gains need contacts");
    for (const auto& c : contacts)
      if (c.friction != contacts.front().friction || c.restitution != contacts.front().restitution)
        throw std::invalid_argument(
            "MechanicalHybridModel: parameter gains need one friction and restitution for every "
            "contact");
    np_ = 2;
    parameter_values_ = Eigen::Vector2d(contacts.front().friction, contacts.front().restitution);
  }
}

Eigen::VectorXd MechanicalHybridModel::state(const Eigen::VectorXd& q,
                                             const Eigen::VectorXd& v) const {
  Eigen::VectorXd x(state_size());
  x.head(nq_) = q;
  x.segment(nq_, nv_) = v;
  x.tail(np_) = parameter_values_.head(np_);
  return x;
}

namespace {
ScalarContext<double> context_of(const Eigen::VectorXd& x, int np) {
  ScalarContext<double> p;
  p.from_state = np > 0;
  if (p.from_state) {
    p.mu = x(x.size() - 2);
    p.e = x(x.size() - 1);
  }
  return p;
}
}  // namespace

void MechanicalHybridModel::check_state(const Eigen::VectorXd& x) const {
  if (x.size() != state_size())
    throw std::invalid_argument("MechanicalHybridModel: state has " + std::to_string(x.size()) +
                                " entries, expected " + std::to_string(state_size()));
  if (!x.allFinite()) throw std::invalid_argument("MechanicalHybridModel: non-finite state");
}

void MechanicalHybridModel::check(const HybridMode& mode, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd* u) const {
  if (static_cast<int>(mode.size()) != num_contacts_)
    throw std::invalid_argument("MechanicalHybridModel: mode has " + std::to_string(mode.size()) +
                                " phases for " + std::to_string(num_contacts_) + " contacts");
  check_state(x);
  if (u != nullptr) {
    if (u->size() != nu_)
      throw std::invalid_argument("MechanicalHybridModel: input has " + std::to_string(u->size()) +
                                  " entries, expected " + std::to_string(nu_));
    if (!u->allFinite()) throw std::invalid_argument("MechanicalHybridModel: non-finite input");
  }
}

Eigen::VectorXd MechanicalHybridModel::flow(const HybridMode& mode, const Eigen::VectorXd& x,
                                            const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const auto r =
      mode_flow<double>(system_, mode, x.head(nq_), x.segment(nq_, nv_), u, context_of(x, np_));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(state_size());  // parameters: zero flow
  f.head(nq_) = r.q_dot;
  f.segment(nq_, nv_) = r.v_dot;
  return f;
}

ModeForces MechanicalHybridModel::mode_forces(const HybridMode& mode, const Eigen::VectorXd& x,
                                              const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const auto r =
      mode_flow<double>(system_, mode, x.head(nq_), x.segment(nq_, nv_), u, context_of(x, np_));
  return {r.v_dot, r.lambda_n, r.lambda_t};
}

FlowLinearisation MechanicalHybridModel::linearise_flow(const HybridMode& mode,
                                                        const Eigen::VectorXd& x,
                                                        const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const int n = state_size();
  const int total = n + nu_;
  const Seeded s = seed(x, u, nq_, nv_);
  const auto r = mode_flow<AutoDiff>(system_ad_, mode, s.q, s.v, s.u, s.context);
  FlowLinearisation out;
  out.f = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n, total);
  for (int i = 0; i < nq_ + nv_; ++i) {
    const AutoDiff& y = i < nq_ ? r.q_dot(i) : r.v_dot(i - nq_);
    out.f(i) = y.value();
    jacobian.row(i) = gradient_of(y, total);
  }
  out.A = jacobian.leftCols(n);
  out.B = jacobian.rightCols(nu_);
  return out;
}

double MechanicalHybridModel::guard_value(const HybridMode& mode, const MicroEvent& event,
                                          const Eigen::VectorXd& x,
                                          const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  return guard_of<double>(system_, mode, event, x.head(nq_), x.segment(nq_, nv_), u,
                          context_of(x, np_));
}

GuardLinearisation MechanicalHybridModel::linearise_guard(const HybridMode& mode,
                                                          const MicroEvent& event,
                                                          const Eigen::VectorXd& x,
                                                          const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const int n = state_size();
  const int total = n + nu_;
  const Seeded s = seed(x, u, nq_, nv_);
  const AutoDiff y = guard_of<AutoDiff>(system_ad_, mode, event, s.q, s.v, s.u, s.context);
  const Eigen::RowVectorXd gradient = gradient_of(y, total);
  return {y.value(), gradient.head(n), gradient.tail(nu_)};
}

Eigen::VectorXd MechanicalHybridModel::reset(const HybridMode& mode, const MicroEvent& event,
                                             const Eigen::VectorXd& x) const {
  check(mode, x, nullptr);
  if (event.kind != GuardKind::kImpact) return x;
  Eigen::VectorXd x_plus = x;
  x_plus.segment(nq_, nv_) = post_impact_velocity<double>(system_, mode, event, x.head(nq_),
                                                          x.segment(nq_, nv_), context_of(x, np_));
  return x_plus;
}

ResetLinearisation MechanicalHybridModel::linearise_reset(const HybridMode& mode,
                                                          const MicroEvent& event,
                                                          const Eigen::VectorXd& x) const {
  check(mode, x, nullptr);
  const int n = state_size();
  if (event.kind != GuardKind::kImpact) return {x, Eigen::MatrixXd::Identity(n, n)};
  const Seeded s = seed(x, Eigen::VectorXd(), nq_, nv_);
  const Vec<AutoDiff> v_plus =
      post_impact_velocity<AutoDiff>(system_ad_, mode, event, s.q, s.v, s.context);
  ResetLinearisation out{x, Eigen::MatrixXd::Identity(n, n)};
  for (int i = 0; i < nv_; ++i) {
    out.x_plus(nq_ + i) = v_plus(i).value();
    out.dx.row(nq_ + i) = gradient_of(v_plus(i), n);
  }
  return out;
}

Eigen::MatrixXd MechanicalHybridModel::mode_constraint_rows(const HybridMode& mode,
                                                            const Eigen::VectorXd& x) const {
  check(mode, x, nullptr);
  const int n = state_size();
  const Seeded s = seed(x, Eigen::VectorXd(), nq_, nv_);
  const auto contacts = contacts_of(system_ad_, s.q, s.v, mode.size(), s.context);
  std::vector<Eigen::RowVectorXd> rows;
  for (int i = 0; i < num_contacts_; ++i) {
    if (!is_closed(mode[i])) continue;
    const Vec<AutoDiff> zeta = relative_velocity_of(contacts[i], s.v, s.context);
    rows.push_back(gradient_of(contacts[i].gap, n));
    rows.push_back(gradient_of(zeta(0), n));
    if (mode[i] == ContactPhase::kStick)
      for (Eigen::Index k = 1; k < zeta.size(); ++k) rows.push_back(gradient_of(zeta(k), n));
  }
  if (nq_ != nv_) {
    // Unit quaternions: the position perturbations must lie in the range of N(q) (q̇ = N v),
    // i.e. be orthogonal to its left null space (the quaternions themselves).
    const Eigen::MatrixXd N = position_rate_matrix(x);
    const Eigen::MatrixXd normal = Eigen::FullPivLU<Eigen::MatrixXd>(N.transpose()).kernel();
    for (Eigen::Index k = 0; k < normal.cols(); ++k) {
      Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(n);
      row.head(nq_) = normal.col(k).transpose();
      rows.push_back(row);
    }
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), n);
  for (std::size_t r = 0; r < rows.size(); ++r) out.row(static_cast<Eigen::Index>(r)) = rows[r];
  return out;
}

Eigen::VectorXd MechanicalHybridModel::gaps(const Eigen::VectorXd& x) const {
  std::vector<model::Contact<double>> contacts;
  system_.find_contacts(x.head(nq_), x.segment(nq_, nv_), kAllContactsMargin, contacts);
  require_contact_count(contacts.size(), static_cast<std::size_t>(num_contacts_));
  Eigen::VectorXd out(num_contacts_);
  for (int i = 0; i < num_contacts_; ++i) out(i) = contacts[i].gap;
  return out;
}

Eigen::MatrixXd MechanicalHybridModel::relative_velocities(const Eigen::VectorXd& x) const {
  std::vector<model::Contact<double>> contacts;
  const Eigen::VectorXd v = x.segment(nq_, nv_);
  system_.find_contacts(x.head(nq_), v, kAllContactsMargin, contacts);
  require_contact_count(contacts.size(), static_cast<std::size_t>(num_contacts_));
  Eigen::MatrixXd out(num_contacts_, 1 + system_.tangent_dim());
  for (int i = 0; i < num_contacts_; ++i) out.row(i) = contacts[i].relative_velocity(v).transpose();
  return out;
}

Eigen::MatrixXd MechanicalHybridModel::position_rate_matrix(const Eigen::VectorXd& x) const {
  // q̇ = N(q) v is linear in v: column j is the rate for the unit velocity e_j.
  Eigen::MatrixXd N(nq_, nv_);
  for (int j = 0; j < nv_; ++j)
    N.col(j) = system_.position_rate(x.head(nq_), Eigen::VectorXd::Unit(nv_, j));
  return N;
}

Eigen::MatrixXd MechanicalHybridModel::tangent_basis(const Eigen::VectorXd& x) const {
  check_state(x);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(state_size(), 2 * nv_ + np_);
  E.topLeftCorner(nq_, nv_) = position_rate_matrix(x);
  E.bottomRightCorner(nv_ + np_, nv_ + np_).setIdentity();
  return E;
}

Eigen::MatrixXd MechanicalHybridModel::tangent_projection(const Eigen::VectorXd& x) const {
  check_state(x);
  const Eigen::MatrixXd N = position_rate_matrix(x);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(2 * nv_ + np_, state_size());
  // Left inverse (NᵀN)⁻¹Nᵀ: exact on the range of N, where perturbations live.
  P.topLeftCorner(nv_, nq_) = (N.transpose() * N).ldlt().solve(N.transpose());
  P.bottomRightCorner(nv_ + np_, nv_ + np_).setIdentity();
  return P;
}

}  // namespace impactbench::sensitivity
