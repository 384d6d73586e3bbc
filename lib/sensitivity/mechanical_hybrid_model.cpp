#include "lib/sensitivity/mechanical_hybrid_model.hpp"
#include "lib/output/number_text.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <algorithm>

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

template <typename Scalar>
std::vector<model::Contact<Scalar>> contacts_of(const model::LagrangianSystem<Scalar>& system,
                                                const Vec<Scalar>& q, const Vec<Scalar>& v,
                                                std::size_t expected) {
  std::vector<model::Contact<Scalar>> out;
  system.find_contacts(q, v, kAllContactsMargin, out);
  require_contact_count(out.size(), expected);
  return out;
}

/// Rows J, columns C, drifts d of the closed contacts (header comment), and where each
/// contact's normal / tangential multiplier sits (−1: none).
template <typename Scalar>
struct ConstraintSet {
  Mat<Scalar> J, C;
  Vec<Scalar> drift;
  std::vector<int> normal_row, tangent_row;
};

template <typename Scalar>
ConstraintSet<Scalar> closed_constraints(const HybridMode& mode,
                                         const std::vector<model::Contact<Scalar>>& contacts,
                                         int nv) {
  const int nc = static_cast<int>(contacts.size());
  int k = 0;
  for (int i = 0; i < nc; ++i)
    k += mode[i] == ContactPhase::kStick ? 2 : (is_closed(mode[i]) ? 1 : 0);
  ConstraintSet<Scalar> set;
  set.J = Mat<Scalar>::Zero(k, nv);
  set.C = Mat<Scalar>::Zero(nv, k);
  set.drift = Vec<Scalar>::Zero(k);
  set.normal_row.assign(nc, -1);
  set.tangent_row.assign(nc, -1);
  int row = 0;
  for (int i = 0; i < nc; ++i) {
    if (!is_closed(mode[i])) continue;
    const auto& c = contacts[i];
    const Vec<Scalar> wn = c.normal_direction(nv);
    const Vec<Scalar> wt = c.tangent_directions(nv).col(0);
    set.normal_row[i] = row;
    set.J.row(row) = wn.transpose();
    set.drift(row) = c.normal_drift;
    if (mode[i] == ContactPhase::kStick) {
      set.C.col(row) = wn;
      ++row;
      set.tangent_row[i] = row;
      set.J.row(row) = wt.transpose();
      set.C.col(row) = wt;
      set.drift(row) = c.tangent_drift(0);
    } else {
      // Slip friction folded into the normal column: λ_t = −μ λ_n s.
      set.C.col(row) = wn - Scalar(c.friction * slip_direction(mode[i])) * wt;
    }
    ++row;
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
                                   const char* what) {
  const std::vector<Eigen::Index> rows = independent_rows(D);
  const Eigen::Index k = D.rows();
  if (static_cast<Eigen::Index>(rows.size()) == k) return solve_dense<Scalar>(D, r, what);
  if (rows.empty()) return Vec<Scalar>::Zero(k);
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
  Vec<Scalar> q_dot, v_dot, lambda_n, lambda_t;
};

template <typename Scalar>
FlowResult<Scalar> mode_flow(const model::LagrangianSystem<Scalar>& system, const HybridMode& mode,
                             const Vec<Scalar>& q, const Vec<Scalar>& v, const Vec<Scalar>& u) {
  const int nv = system.num_velocities();
  const auto contacts = contacts_of(system, q, v, mode.size());
  const Mat<Scalar> M = Mat<Scalar>(system.mass_matrix(q));
  Vec<Scalar> force = -system.bias_forces(q, v);
  if (system.num_inputs() > 0) force += system.input_matrix(q) * u;
  const ConstraintSet<Scalar> set = closed_constraints(mode, contacts, nv);
  // One elimination for M⁻¹ [force, C].
  Mat<Scalar> rhs_columns(nv, 1 + set.C.cols());
  rhs_columns << force, set.C;
  const Mat<Scalar> solved = solve_dense<Scalar>(M, rhs_columns, "the mass matrix");

  FlowResult<Scalar> out;
  out.q_dot = system.position_rate(q, v);
  out.v_dot = solved.col(0);
  const int nc = static_cast<int>(contacts.size());
  out.lambda_n = Vec<Scalar>::Zero(nc);
  out.lambda_t = Vec<Scalar>::Zero(nc);
  if (set.J.rows() == 0) return out;

  const Mat<Scalar> m_inv_c = solved.rightCols(set.C.cols());
  const Mat<Scalar> delassus = set.J * m_inv_c;
  const Vec<Scalar> rhs = -set.drift - set.J * out.v_dot;
  const char* what = "the constraint matrix J M^-1 C of the flow";
  Vec<Scalar> weights;  // empty: plain least norm
  Vec<Scalar> lambda = constraint_multipliers<Scalar>(delassus, rhs, weights, what);
  if (independent_rows(delassus).size() < static_cast<std::size_t>(delassus.rows())) {
    // Redundant sticking contacts: split their tangential forces in proportion to their normal
    // forces (weights w = λ_n on the tangential entries), so that all contacts of a redundant
    // group reach their cones together, exactly when the total force leaves the total cone
    // (|Σλ_t| = μ Σλ_n): the rigid body's slip condition. λ_n itself is determined.
    weights = Vec<Scalar>::Ones(delassus.rows());
    double largest = 0.0;
    for (int i = 0; i < nc; ++i)
      if (set.normal_row[i] >= 0)
        largest = std::max(largest, std::abs(value_of(lambda(set.normal_row[i]))));
    const double floor = std::max(1e-9 * largest, std::numeric_limits<double>::min());
    bool any = false;
    for (int i = 0; i < nc; ++i) {
      if (set.tangent_row[i] < 0) continue;
      const Scalar ln = lambda(set.normal_row[i]);
      weights(set.tangent_row[i]) = value_of(ln) > floor ? ln : Scalar(floor);
      any = true;
    }
    if (any)
      lambda = constraint_multipliers<Scalar>(delassus, rhs, weights, what);
    else
      weights.resize(0);
  }
  out.v_dot += m_inv_c * lambda;
  // One step of iterative refinement on the constraint residual J v̇ + d: a body held by its
  // contacts (v̇ = 0 as the difference of gravity and contact forces) would otherwise drift by
  // the round-off of that difference, ~1e-15 m/s², which sets the noise floor of the ε-tests.
  const Vec<Scalar> residual = -set.drift - set.J * out.v_dot;
  const Vec<Scalar> correction = constraint_multipliers<Scalar>(delassus, residual, weights, what);
  lambda += correction;
  out.v_dot += m_inv_c * correction;
  for (int i = 0; i < nc; ++i) {
    if (set.normal_row[i] < 0) continue;
    out.lambda_n(i) = lambda(set.normal_row[i]);
    out.lambda_t(i) =
        set.tangent_row[i] >= 0
            ? Scalar(lambda(set.tangent_row[i]))
            : Scalar(-contacts[i].friction * slip_direction(mode[i]) * lambda(set.normal_row[i]));
  }
  return out;
}

template <typename Scalar>
Vec<Scalar> post_impact_velocity(const model::LagrangianSystem<Scalar>& system,
                                 const HybridMode& mode, const MicroEvent& event,
                                 const Vec<Scalar>& q, const Vec<Scalar>& v) {
  const int nv = system.num_velocities();
  const auto contacts = contacts_of(system, q, v, mode.size());
  const HybridMode after = apply_event(mode, event);
  const auto& impacting = contacts[event.contact];
  const double e = impacting.restitution;
  if (is_closed(event.phase_after) && e > 0.0)
    throw std::invalid_argument(
        "MechanicalHybridModel: an impact with restitution e = " + std::to_string(e) +
        " cannot leave contact " + std::to_string(event.contact) + " closed");
  ConstraintSet<Scalar> set = closed_constraints(after, contacts, nv);
  const Vec<Scalar> zeta = impacting.relative_velocity(v);
  if (!is_closed(event.phase_after)) {
    // Bounce: the impacting contact's normal row; its friction as a tangential row with target
    // ζ_t⁺ = 0 (stick impulse), or folded into the normal column along s (slip impulse; s from
    // ζ_t⁻ unless given; zero friction if μ = 0 or no tangential velocity).
    const Vec<Scalar> wn = impacting.normal_direction(nv);
    const Vec<Scalar> wt = impacting.tangent_directions(nv).col(0);
    const bool stick = event.bounce_impulse == ContactPhase::kStick && impacting.friction > 0.0;
    const Eigen::Index row = set.J.rows();
    set.J.conservativeResize(row + (stick ? 2 : 1), Eigen::NoChange);
    set.C.conservativeResize(Eigen::NoChange, row + (stick ? 2 : 1));
    set.J.row(row) = wn.transpose();
    set.normal_row[event.contact] = static_cast<int>(row);
    if (stick) {
      set.C.col(row) = wn;
      set.J.row(row + 1) = wt.transpose();
      set.C.col(row + 1) = wt;
      set.tangent_row[event.contact] = static_cast<int>(row + 1);
    } else {
      const double zt = value_of(zeta(1));
      const int given = slip_direction(event.bounce_impulse);
      const double s = given != 0 ? given : (zt > 0.0 ? 1.0 : (zt < 0.0 ? -1.0 : 0.0));
      set.C.col(row) = wn - Scalar(impacting.friction * s) * wt;
    }
  }
  Vec<Scalar> target = Vec<Scalar>::Zero(set.J.rows());
  target(set.normal_row[event.contact]) = Scalar(-e) * zeta(0);

  const Mat<Scalar> M = Mat<Scalar>(system.mass_matrix(q));
  const Mat<Scalar> m_inv_c = solve_dense<Scalar>(M, set.C, "the mass matrix");
  const Mat<Scalar> delassus = set.J * m_inv_c;
  const Vec<Scalar> impulse =
      constraint_multipliers<Scalar>(delassus, Vec<Scalar>(target - set.J * v), Vec<Scalar>(),
                                     "the impulse matrix J M^-1 C of the impact");
  return v + m_inv_c * impulse;
}

template <typename Scalar>
Scalar guard_of(const model::LagrangianSystem<Scalar>& system, const HybridMode& mode,
                const MicroEvent& event, const Vec<Scalar>& q, const Vec<Scalar>& v,
                const Vec<Scalar>& u) {
  const ContactPhase phase = mode[event.contact];
  const auto wrong = [&](const char* needed) {
    return std::invalid_argument(
        "MechanicalHybridModel: guard " + std::string(to_string(event.kind)) + " needs contact " +
        std::to_string(event.contact) + " " + needed + ", it is " + std::string(to_string(phase)));
  };
  switch (event.kind) {
    case GuardKind::kImpact: {
      if (is_closed(phase)) throw wrong("open");
      return contacts_of(system, q, v, mode.size())[event.contact].gap;
    }
    case GuardKind::kSlipToStick: {
      if (slip_direction(phase) == 0) throw wrong("slipping");
      return Scalar(slip_direction(phase)) *
             contacts_of(system, q, v, mode.size())[event.contact].relative_velocity(v)(1);
    }
    case GuardKind::kLiftOff: {
      if (!is_closed(phase)) throw wrong("closed");
      return mode_flow(system, mode, q, v, u).lambda_n(event.contact);
    }
    case GuardKind::kStickToSlip: {
      if (phase != ContactPhase::kStick) throw wrong("sticking");
      const int s = slip_direction(event.phase_after);
      if (s == 0)
        throw std::invalid_argument(
            "MechanicalHybridModel: a stick-to-slip event must lead to slip+ or slip-");
      const auto forces = mode_flow(system, mode, q, v, u);
      const double mu = contacts_of(system, q, v, mode.size())[event.contact].friction;
      return Scalar(mu) * forces.lambda_n(event.contact) +
             Scalar(s) * forces.lambda_t(event.contact);
    }
  }
  throw std::logic_error("MechanicalHybridModel: unknown guard kind");
}

/// AD variables for (x, u) seeded with the identity over n + m directions.
struct Seeded {
  Vec<AutoDiff> q, v, u;
};
Seeded seed(const Eigen::VectorXd& x, const Eigen::VectorXd& u, int nq) {
  const int total = static_cast<int>(x.size() + u.size());
  Seeded s;
  s.q.resize(nq);
  s.v.resize(x.size() - nq);
  s.u.resize(u.size());
  for (int i = 0; i < x.size(); ++i) {
    const AutoDiff var(x(i), total, i);
    if (i < nq)
      s.q(i) = var;
    else
      s.v(i - nq) = var;
  }
  for (int j = 0; j < u.size(); ++j) s.u(j) = AutoDiff(u(j), total, static_cast<int>(x.size()) + j);
  return s;
}

/// d(output)/d(seeded variables), `total` columns (an output without derivatives is constant).
Eigen::RowVectorXd gradient_of(const AutoDiff& y, int total) {
  if (y.derivatives().size() == 0) return Eigen::RowVectorXd::Zero(total);
  return y.derivatives().transpose();
}

}  // namespace

MechanicalHybridModel::MechanicalHybridModel(const model::LagrangianSystem<double>& system,
                                             const model::LagrangianSystem<AutoDiff>& system_ad)
    : system_(system), system_ad_(system_ad) {
  if (system.tangent_dim() != 1)
    throw std::invalid_argument("MechanicalHybridModel: planar systems only (tangent_dim 1)");
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
}

void MechanicalHybridModel::check(const HybridMode& mode, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd* u) const {
  if (static_cast<int>(mode.size()) != num_contacts_)
    throw std::invalid_argument("MechanicalHybridModel: mode has " + std::to_string(mode.size()) +
                                " phases for " + std::to_string(num_contacts_) + " contacts");
  if (x.size() != state_size())
    throw std::invalid_argument("MechanicalHybridModel: state has " + std::to_string(x.size()) +
                                " entries, expected " + std::to_string(state_size()));
  if (!x.allFinite()) throw std::invalid_argument("MechanicalHybridModel: non-finite state");
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
  const auto r = mode_flow<double>(system_, mode, x.head(nq_), x.tail(nv_), u);
  Eigen::VectorXd f(state_size());
  f << r.q_dot, r.v_dot;
  return f;
}

ModeForces MechanicalHybridModel::mode_forces(const HybridMode& mode, const Eigen::VectorXd& x,
                                              const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const auto r = mode_flow<double>(system_, mode, x.head(nq_), x.tail(nv_), u);
  return {r.v_dot, r.lambda_n, r.lambda_t};
}

FlowLinearisation MechanicalHybridModel::linearise_flow(const HybridMode& mode,
                                                        const Eigen::VectorXd& x,
                                                        const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const int n = state_size();
  const int total = n + nu_;
  const Seeded s = seed(x, u, nq_);
  const auto r = mode_flow<AutoDiff>(system_ad_, mode, s.q, s.v, s.u);
  FlowLinearisation out;
  out.f.resize(n);
  Eigen::MatrixXd jacobian(n, total);
  for (int i = 0; i < n; ++i) {
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
  return guard_of<double>(system_, mode, event, x.head(nq_), x.tail(nv_), u);
}

GuardLinearisation MechanicalHybridModel::linearise_guard(const HybridMode& mode,
                                                          const MicroEvent& event,
                                                          const Eigen::VectorXd& x,
                                                          const Eigen::VectorXd& u) const {
  check(mode, x, &u);
  const int n = state_size();
  const int total = n + nu_;
  const Seeded s = seed(x, u, nq_);
  const AutoDiff y = guard_of<AutoDiff>(system_ad_, mode, event, s.q, s.v, s.u);
  const Eigen::RowVectorXd gradient = gradient_of(y, total);
  return {y.value(), gradient.head(n), gradient.tail(nu_)};
}

Eigen::VectorXd MechanicalHybridModel::reset(const HybridMode& mode, const MicroEvent& event,
                                             const Eigen::VectorXd& x) const {
  check(mode, x, nullptr);
  if (event.kind != GuardKind::kImpact) return x;
  Eigen::VectorXd x_plus = x;
  x_plus.tail(nv_) = post_impact_velocity<double>(system_, mode, event, x.head(nq_), x.tail(nv_));
  return x_plus;
}

ResetLinearisation MechanicalHybridModel::linearise_reset(const HybridMode& mode,
                                                          const MicroEvent& event,
                                                          const Eigen::VectorXd& x) const {
  check(mode, x, nullptr);
  const int n = state_size();
  if (event.kind != GuardKind::kImpact) return {x, Eigen::MatrixXd::Identity(n, n)};
  const Seeded s = seed(x, Eigen::VectorXd(), nq_);
  const Vec<AutoDiff> v_plus = post_impact_velocity<AutoDiff>(system_ad_, mode, event, s.q, s.v);
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
  const Seeded s = seed(x, Eigen::VectorXd(), nq_);
  const auto contacts = contacts_of(system_ad_, s.q, s.v, mode.size());
  std::vector<Eigen::RowVectorXd> rows;
  for (int i = 0; i < num_contacts_; ++i) {
    if (!is_closed(mode[i])) continue;
    const Vec<AutoDiff> zeta = contacts[i].relative_velocity(s.v);
    rows.push_back(gradient_of(contacts[i].gap, n));
    rows.push_back(gradient_of(zeta(0), n));
    if (mode[i] == ContactPhase::kStick) rows.push_back(gradient_of(zeta(1), n));
  }
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows.size()), n);
  for (std::size_t r = 0; r < rows.size(); ++r) out.row(static_cast<Eigen::Index>(r)) = rows[r];
  return out;
}

Eigen::VectorXd MechanicalHybridModel::gaps(const Eigen::VectorXd& x) const {
  std::vector<model::Contact<double>> contacts;
  system_.find_contacts(x.head(nq_), x.tail(nv_), kAllContactsMargin, contacts);
  require_contact_count(contacts.size(), static_cast<std::size_t>(num_contacts_));
  Eigen::VectorXd out(num_contacts_);
  for (int i = 0; i < num_contacts_; ++i) out(i) = contacts[i].gap;
  return out;
}

Eigen::MatrixXd MechanicalHybridModel::relative_velocities(const Eigen::VectorXd& x) const {
  std::vector<model::Contact<double>> contacts;
  const Eigen::VectorXd v = x.tail(nv_);
  system_.find_contacts(x.head(nq_), v, kAllContactsMargin, contacts);
  require_contact_count(contacts.size(), static_cast<std::size_t>(num_contacts_));
  Eigen::MatrixXd out(num_contacts_, 2);
  for (int i = 0; i < num_contacts_; ++i) out.row(i) = contacts[i].relative_velocity(v).transpose();
  return out;
}

}  // namespace impactbench::sensitivity
