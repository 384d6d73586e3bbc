#pragma once
// The data the adapters hand to the Siconos side (siconos_event_driven_model.hpp,
// siconos_lagrangian_model.hpp), in Eigen and the standard library only: the files that include
// Siconos are compiled as C++17 (tools/CMakeLists.txt: every *_model.cpp here), because Siconos
// 4.4's Simulation.hpp instantiates a Boost 1.74 uBLAS constructor that calls
// std::allocator::construct, which C++20 removed; the rest of the project is C++20.
#include <Eigen/Core>

namespace impactbench::adapters::siconos {

/// A planar body in (x, y, θ) with a constant external force (the event-driven scheme).
struct PlanarBody {
  Eigen::Vector3d q = Eigen::Vector3d::Zero();  ///< (x, y, θ)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  Eigen::Vector3d mass_diagonal = Eigen::Vector3d::Ones();  ///< (m, m, I)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();          ///< external force (x, y, torque)
};

/// Siconos Numerics' fc2d solvers; in space (fc3d) only nsgs is offered.
enum class Fc2dSolver { kNsgs, kLemke, kEnum, kCpg };

/// Siconos' Moreau–Jean time-stepping (siconos_moreau_jean_stepping.hpp).
struct Scheme {
  double dt = 1e-3;
  double duration = 1.0;  ///< past the last step's end (Siconos fails an assertion at its end)
  double theta = 0.5;
  double gamma = 0.5;
  double activation_threshold = 0.0;
  Fc2dSolver solver = Fc2dSolver::kNsgs;
  int contact_dimension = 2;  ///< 2: planar (fc2d), 3: spatial (fc3d)
  double tolerance = 1e-10;
  int max_iterations = 1000;
};

}  // namespace impactbench::adapters::siconos
