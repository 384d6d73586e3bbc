#pragma once
// The Siconos side of the siconos engine, behind an interface of Eigen and the standard library
// only: its source is compiled as C++17 (tools/CMakeLists.txt), because Siconos 4.4's
// Simulation.hpp instantiates a Boost 1.74 uBLAS constructor that calls
// std::allocator::construct, which C++20 removed.
//
// Planar bodies as LagrangianLinearTIDS in q = (x, y, θ) with a constant external force, each
// contact an Interaction with a NewtonImpactFrictionNSL and a LagrangianLinearTIR y = H q + b
// (row 0 the normal gap, row 1 the tangential displacement), one MoreauJeanOSI, a
// FrictionContact of dimension 2 and a TimeStepping in fixed steps.
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace impactbench::adapters::siconos {

struct PlanarBody {
  Eigen::Vector3d q = Eigen::Vector3d::Zero();  ///< (x, y, θ)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  Eigen::Vector3d mass_diagonal = Eigen::Vector3d::Ones();  ///< (m, m, I)
  Eigen::Vector3d force = Eigen::Vector3d::Zero();          ///< external force until set_force
};

struct PlanarContact {
  int body = 0;
  Eigen::Matrix<double, 2, 3> h = Eigen::Matrix<double, 2, 3>::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  double restitution = 0.0;
  double friction = 0.0;
};

/// Siconos Numerics' fc2d solvers.
enum class Fc2dSolver { kNsgs, kLemke, kEnum, kCpg };

struct Scheme {
  double dt = 1e-3;
  double duration = 1.0;  ///< past the last step's end (Siconos fails an assertion at its end)
  double theta = 0.5;
  double gamma = 0.5;
  double activation_threshold = 0.0;
  Fc2dSolver solver = Fc2dSolver::kNsgs;
  double tolerance = 1e-10;
  int max_iterations = 1000;
};

class PlanarModel {
 public:
  /// Throws std::runtime_error with Siconos' message (first line) when Siconos refuses.
  PlanarModel(const std::vector<PlanarBody>& bodies, const std::vector<PlanarContact>& contacts,
              const Scheme& scheme);
  ~PlanarModel();
  PlanarModel(const PlanarModel&) = delete;
  PlanarModel& operator=(const PlanarModel&) = delete;

  /// The external force on `body` (x, y, torque), held over the next steps.
  void set_force(int body, const Eigen::Vector3d& force);
  /// One step of Siconos' TimeStepping (computeOneStep, nextStep).
  void step();
  Eigen::Vector3d q(int body) const;
  Eigen::Vector3d v(int body) const;
  /// The contact's impulse of the last step, (normal, tangent) [N·s].
  Eigen::Vector2d impulse(int contact) const;
  /// The solver's iterations and residual of its last solve.
  int iterations() const;
  double residual() const;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace impactbench::adapters::siconos
