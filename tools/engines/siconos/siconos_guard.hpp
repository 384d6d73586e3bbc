#pragma once
// Helpers shared by the files that include Siconos (compiled as C++17, see
// siconos_scheme.hpp): vectors between Eigen and Siconos, a planar body, and Siconos'
// exceptions as one line. Include it only from those files.
#include <siconos/numerics/Friction_cst.h>
#include <siconos/kernel/LagrangianLinearTIDS.hpp>
#include <siconos/kernel/SiconosException.hpp>
#include <siconos/kernel/SiconosVector.hpp>
#include <siconos/kernel/SimpleMatrix.hpp>

#include <boost/exception/get_error_info.hpp>

#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "tools/engines/siconos/siconos_scheme.hpp"

namespace impactbench::adapters::siconos {

inline SP::SiconosVector siconos_vector(const Eigen::VectorXd& x) {
  auto v = std::make_shared<SiconosVector>(static_cast<unsigned>(x.size()));
  for (Eigen::Index i = 0; i < x.size(); ++i) (*v)(static_cast<unsigned>(i)) = x[i];
  return v;
}

inline Eigen::Vector3d eigen3(const SiconosVector& v) {
  return Eigen::Vector3d(v(0), v(1), v(2));
}

/// Siconos Numerics' id of a friction solver for contacts of `dimension` 2 or 3 (in space
/// nsgs alone: the adapters refuse the others before).
inline int friction_solver_id(Fc2dSolver solver, int dimension) {
  if (dimension == 3) {
    if (solver != Fc2dSolver::kNsgs) throw std::logic_error("fc3d: nsgs only");
    return SICONOS_FRICTION_3D_NSGS;
  }
  switch (solver) {
    case Fc2dSolver::kNsgs:
      return SICONOS_FRICTION_2D_NSGS;
    case Fc2dSolver::kLemke:
      return SICONOS_FRICTION_2D_LEMKE;
    case Fc2dSolver::kEnum:
      return SICONOS_FRICTION_2D_ENUM;
    case Fc2dSolver::kCpg:
      return SICONOS_FRICTION_2D_CPG;
  }
  throw std::logic_error("unknown fc2d solver");
}

/// A planar body as a LagrangianLinearTIDS in (x, y, θ) with `force` as its external force
/// (held by pointer: changing it in place changes the force).
inline SP::LagrangianLinearTIDS planar_ds(const PlanarBody& body, const SP::SiconosVector& force) {
  auto mass = std::make_shared<SimpleMatrix>(3, 3, 0.0);
  for (unsigned i = 0; i < 3; ++i) (*mass)(i, i) = body.mass_diagonal[i];
  auto ds =
      std::make_shared<LagrangianLinearTIDS>(siconos_vector(body.q), siconos_vector(body.v), mass);
  ds->setFExtPtr(force);
  return ds;
}

/// Runs f; a Siconos exception becomes its message (what() says only "std::exception"), any
/// other the first line of what() (file, line and errno lines follow in some).
template <typename F>
auto guarded(F&& f) {
  try {
    return f();
  } catch (const Siconos::exception& error) {
    const std::string* message = boost::get_error_info<Siconos::exception::extra_message>(error);
    throw std::runtime_error("siconos: " + (message ? *message : std::string(error.what())));
  } catch (const std::exception& error) {
    const std::string text = error.what();
    throw std::runtime_error("siconos: " + text.substr(0, text.find('\n')));
  }
}

}  // namespace impactbench::adapters::siconos
