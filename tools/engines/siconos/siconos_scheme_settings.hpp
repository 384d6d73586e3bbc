#pragma once
// The Siconos settings (engines::SiconosSettings) as the Siconos side's Scheme: the settings
// live in the library, the Siconos side sees Eigen and the standard library only.
#include <stdexcept>

#include "tools/engines/siconos/siconos_scheme.hpp"
#include "tools/engines/siconos/siconos_settings.hpp"

namespace impactbench::adapters {

inline siconos::Fc2dSolver fc2d_solver(engines::SiconosSolver solver) {
  switch (solver) {
    case engines::SiconosSolver::kNsgs:
      return siconos::Fc2dSolver::kNsgs;
    case engines::SiconosSolver::kLemke:
      return siconos::Fc2dSolver::kLemke;
    case engines::SiconosSolver::kEnum:
      return siconos::Fc2dSolver::kEnum;
    case engines::SiconosSolver::kCpg:
      return siconos::Fc2dSolver::kCpg;
  }
  throw std::logic_error("unknown Siconos solver");
}

/// Siconos' Moreau–Jean scheme for `steps` steps of h (the simulation's end a step past the
/// last: Siconos fails an assertion at its end).
inline siconos::Scheme moreau_jean_scheme(const engines::SiconosSettings& settings, double h,
                                          long steps) {
  siconos::Scheme scheme;
  scheme.dt = h;
  scheme.duration = static_cast<double>(steps + 1) * h;
  scheme.theta = settings.theta;
  scheme.gamma = settings.gamma;
  scheme.activation_threshold = settings.activation_threshold;
  scheme.solver = fc2d_solver(settings.solver);
  scheme.tolerance = settings.tolerance;
  scheme.max_iterations = settings.max_iterations;
  return scheme;
}

}  // namespace impactbench::adapters
