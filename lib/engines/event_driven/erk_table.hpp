#pragma once
// The Butcher tables of the explicit Runge–Kutta pairs (EventDrivenOptions::erk_pair), as
// ARKODE ships them: its table ID for ERKStep (method = erk), and the coefficients themselves for
// our own driver of the same pairs (method = own_erk, own_erk_session.hpp).
#include <cstdio>  // arkode_butcher.h uses FILE without including it

#include <arkode/arkode_butcher_erk.h>
#include <Eigen/Core>

#include "lib/engines/event_driven/event_driven_options.hpp"

namespace impactbench::engines::event_driven {

/// ARKODE's ID of the pair's table.
ARKODE_ERKTableID arkode_erk_table(ErkPair pair);

/// An embedded explicit pair: stages k_i = f(t + c_i h, y + h Σ_{j<i} a_ij k_j); the step
/// y + h Σ b_i k_i is of order `order`, the embedded y + h Σ d_i k_i of order `embedding_order`.
struct ButcherPair {
  Eigen::MatrixXd a;  ///< stages × stages, strictly lower triangular
  Eigen::VectorXd b, c, d;
  int order = 0;
  int embedding_order = 0;
  /// First same as last: the last stage is evaluated at the step's end (c = 1, its row of a is
  /// b), so it is f at the new state and serves as the next step's first stage.
  bool first_same_as_last = false;
  /// The weights e of a continuous extension of order 4 built on the cubic Hermite interpolant
  /// H(θ) through y and ẏ at both ends of the step: y(θ) = H(θ) + θ² (1 − θ)² h Σ e_i k_i,
  /// θ = (t − t₀)/h. Empty where the pair has none (its dense output is H alone, of order 3).
  Eigen::VectorXd quartic_correction;
  int stages() const { return static_cast<int>(b.size()); }
};

/// The pair's coefficients, from ARKODE's table, and for Dormand–Prince 5(4) its continuous
/// extension of order 4 (Hairer, Nørsett & Wanner, Solving Ordinary Differential Equations I,
/// 2nd ed., Springer 1993, section II.6, after Dormand & Prince 1986), which needs no right-hand
/// side beyond the step's seven stages.
ButcherPair load_butcher_pair(ErkPair pair);

}  // namespace impactbench::engines::event_driven
