# MuJoCo and ODE, found the same way by the build (dependencies.cmake) and by an installed
# package's consumers (impactbenchConfig.cmake), so both name the same targets.
# MuJoCo 2.2.2 (libmujoco-dev): its mujocoConfig.cmake fails as packaged (it names a qhull
# include directory the package does not ship), so the header and library are looked up
# directly. ODE 0.16 (libode-dev, double precision) has a usable pkg-config file.
if(NOT TARGET impactbench_mujoco)
  find_path(MUJOCO_INCLUDE_DIR mujoco/mujoco.h REQUIRED)
  find_library(MUJOCO_LIBRARY mujoco REQUIRED)
  add_library(impactbench_mujoco INTERFACE IMPORTED)
  target_include_directories(impactbench_mujoco SYSTEM INTERFACE ${MUJOCO_INCLUDE_DIR})
  target_link_libraries(impactbench_mujoco INTERFACE ${MUJOCO_LIBRARY})
endif()
pkg_check_modules(ODE REQUIRED IMPORTED_TARGET ode)
