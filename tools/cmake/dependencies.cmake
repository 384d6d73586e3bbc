# Every dependency is a Debian 12 package; see README.md ("Dependencies") for why each was chosen.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)          # libeigen3-dev
find_package(tomlplusplus REQUIRED)                  # libtomlplusplus-dev: scenario files
find_package(muparser REQUIRED)                      # libmuparser-dev: parameter expressions
find_package(CLI11 REQUIRED)                         # libcli11-dev: command line
find_package(SUNDIALS REQUIRED COMPONENTS cvode arkode nvecserial)  # libsundials-dev: event-driven flow
find_package(box2d CONFIG REQUIRED)                  # libbox2d-dev: planar reference engine
find_package(PkgConfig REQUIRED)
# Bullet's CMake config is unusable as packaged; the double-precision pkg-config file is not.
pkg_check_modules(BULLET REQUIRED IMPORTED_TARGET bullet-float64)  # libbullet-dev
pkg_check_modules(FCLIB REQUIRED IMPORTED_TARGET fclib)            # libfclib-dev: FCLIB problem files
include(${CMAKE_CURRENT_LIST_DIR}/find_mujoco_ode.cmake)  # libmujoco-dev, libode-dev: reference engines
if(IMPACTBENCH_BUILD_TESTS)
  find_package(GTest REQUIRED)                       # libgtest-dev
endif()
if(IMPACTBENCH_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)                   # libbenchmark-dev
endif()

# Optional, never required: Siconos Numerics (Debian libsiconos-numerics-dev) for
# bench/siconos_bench only. Debian's siconos-config.cmake is not usable here: it imports the
# targets of every Siconos component (kernel, io, ...) although the numerics package ships only
# libsiconos_numerics, so find_package(siconos) fails, and it forces CMAKE_CXX_STANDARD 11.
# The numerics headers and library are therefore looked up directly.
if(IMPACTBENCH_WITH_SICONOS AND IMPACTBENCH_BUILD_BENCHMARKS)
  find_path(SICONOS_NUMERICS_INCLUDE_DIR siconos/numerics/fc3d_Solvers.h)
  find_library(SICONOS_NUMERICS_LIBRARY siconos_numerics)
  if(SICONOS_NUMERICS_INCLUDE_DIR AND SICONOS_NUMERICS_LIBRARY)
    add_library(impactbench_siconos_numerics INTERFACE IMPORTED)
    target_include_directories(impactbench_siconos_numerics SYSTEM INTERFACE
      ${SICONOS_NUMERICS_INCLUDE_DIR}/siconos ${SICONOS_NUMERICS_INCLUDE_DIR}/siconos/numerics)
    target_link_libraries(impactbench_siconos_numerics INTERFACE ${SICONOS_NUMERICS_LIBRARY})
    message(STATUS "Siconos Numerics found (${SICONOS_NUMERICS_LIBRARY}): building siconos_bench")
  else()
    message(STATUS "Siconos Numerics not found: siconos_bench is not built (optional)")
  endif()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/find_siconos_kernel.cmake)  # optional: --engine siconos
