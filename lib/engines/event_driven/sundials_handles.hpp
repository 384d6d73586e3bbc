#pragma once
// RAII handles for the SUNDIALS 6 objects both flow sessions share (the context and serial
// vectors), and an Eigen view of a serial vector.
#include <memory>

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <Eigen/Core>

namespace impactbench::engines::event_driven {

struct SunContextDeleter {
  void operator()(SUNContext ctx) const { SUNContext_Free(&ctx); }
};
struct SunVectorDeleter {
  void operator()(_generic_N_Vector* v) const { N_VDestroy(v); }
};
using SunContextPtr = std::unique_ptr<_SUNContext, SunContextDeleter>;
using SunVectorPtr = std::unique_ptr<_generic_N_Vector, SunVectorDeleter>;

inline Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
  return {N_VGetArrayPointer_Serial(v), static_cast<Eigen::Index>(N_VGetLength_Serial(v))};
}

}  // namespace impactbench::engines::event_driven
