#pragma once
// What every part of one event-driven run reads: the system, the options, the input u(t) and
// the sizes, with the few state helpers they share. Holds references: the run's arguments
// outlive it.
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "lib/engines/event_driven/dynamics_at_state.hpp"
#include "lib/engines/event_driven/event_driven_options.hpp"
#include "lib/model/lagrangian_system.hpp"

namespace impactbench::engines::event_driven {

class RunContext {
 public:
  using Input = std::function<Eigen::VectorXd(double)>;

  RunContext(const model::LagrangianSystem<double>& system, const EventDrivenOptions& options,
             const Input& input)
      : system(system),
        options(options),
        input(input),
        nq(system.num_positions()),
        nv(system.num_velocities()),
        constant_mass_(constant_mass_factor(system)) {}

  const model::LagrangianSystem<double>& system;
  const EventDrivenOptions& options;
  const Input& input;
  const int nq, nv;

  /// The factor of M(q): factorised once per run when M does not depend on q.
  std::shared_ptr<const MassFactor> mass_factor(const Eigen::VectorXd& q) const;
  /// M(q)⁻¹ rhs into out (size nv); with a constant M without copying the shared factor's
  /// pointer (an atomic count per right-hand side).
  void solve_mass(const Eigen::VectorXd& q, const Eigen::VectorXd& rhs,
                  Eigen::Ref<Eigen::VectorXd> out) const {
    if (constant_mass_)
      constant_mass_->solve(rhs, out);
    else
      mass_factor(q)->solve(rhs, out);
  }
  /// M(q) and f = S u(t) − H at (t, q, v).
  DynamicsAtState dynamics_at(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v) const {
    return {mass_factor(q), system, q, v, input_at(t)};
  }
  /// u(t); throws std::invalid_argument for a wrong size or a non-finite value.
  Eigen::VectorXd input_at(double t) const;
  /// The contacts within options.contact_margin.
  void find_contacts(const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                     std::vector<model::Contact<double>>& out) const {
    system.find_contacts(q, v, options.contact_margin, out);
  }
  /// q with unit quaternions (q itself when positions are velocities' integrals).
  Eigen::VectorXd normalized_positions(const Eigen::VectorXd& q) const;

 private:
  /// The factor of M for a system whose M does not depend on q, else null.
  static std::shared_ptr<const MassFactor> constant_mass_factor(
      const model::LagrangianSystem<double>& system);

  std::shared_ptr<const MassFactor> constant_mass_;
};

/// The index of the entry with `key` in a list of contacts or of their gaps, looking first at
/// `hint` (see find_contact below); −1 when there is none.
template <typename Keyed>
std::ptrdiff_t index_of_key(const std::vector<Keyed>& list, const model::ContactKey& key,
                            std::size_t hint) {
  if (hint < list.size() && list[hint].key == key) return static_cast<std::ptrdiff_t>(hint);
  for (std::size_t i = 0; i < list.size(); ++i)
    if (list[i].key == key) return static_cast<std::ptrdiff_t>(i);
  return -1;
}

/// The contact with `key`, or nullptr.
const model::Contact<double>* find_contact(const std::vector<model::Contact<double>>& contacts,
                                           const model::ContactKey& key);
/// The same, looking first at `hint`: the system lists contacts in a fixed order, so while the
/// contact set of a segment is unchanged the k-th slot is the k-th contact. Without the hint
/// every guard evaluation was a search per slot: (pairs)² per right-hand side, N⁴ in the number
/// of balls of a cradle.
const model::Contact<double>* find_contact(const std::vector<model::Contact<double>>& contacts,
                                           const model::ContactKey& key, std::size_t hint);

}  // namespace impactbench::engines::event_driven
