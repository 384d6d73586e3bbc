# `cmake --install`: the program, its data (scenarios, scripts, FCLIB files), the benchmark
# binaries (bench/CMakeLists.txt) and a CMake package: find_package(impactbench) gives
# impactbench::lib (model, scenarios, engines), impactbench::solvers (Eigen-only contact
# solvers), impactbench::solver_io (problem files) and impactbench::adapters (compare, with the
# engine registry and every engine's library). Headers keep their source paths below
# include/impactbench.
include(CMakePackageConfigHelpers)

install(TARGETS impactbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set_target_properties(impactbench_lib PROPERTIES EXPORT_NAME lib)
set_target_properties(impactbench_solvers PROPERTIES EXPORT_NAME solvers)
set_target_properties(impactbench_solver_io PROPERTIES EXPORT_NAME solver_io)
set_target_properties(impactbench_adapters PROPERTIES EXPORT_NAME adapters)
set_target_properties(impactbench_flags PROPERTIES EXPORT_NAME flags)
install(TARGETS impactbench_lib impactbench_solvers impactbench_solver_io impactbench_adapters
                impactbench_flags ${impactbench_engine_libraries}
        EXPORT impactbenchTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT impactbenchTargets NAMESPACE impactbench::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/impactbench)

set(impactbench_include ${CMAKE_INSTALL_INCLUDEDIR}/impactbench)
install(DIRECTORY lib solvers DESTINATION ${impactbench_include} FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY tools/engines tools/compare DESTINATION ${impactbench_include}/tools
        FILES_MATCHING PATTERN "*.hpp")

set(impactbench_share ${CMAKE_INSTALL_DATADIR}/impactbench)
install(DIRECTORY scenarios/ DESTINATION ${impactbench_share}/scenarios)
file(GLOB impactbench_scripts ${PROJECT_SOURCE_DIR}/tools/*.py)
install(FILES ${impactbench_scripts} DESTINATION ${impactbench_share}/scripts)
install(DIRECTORY tests/data/fclib/ DESTINATION ${impactbench_share}/fclib)
install(DIRECTORY tests/data/lcp_siconos/ DESTINATION ${impactbench_share}/lcp_siconos)

configure_package_config_file(tools/cmake/impactbenchConfig.cmake.in
  ${PROJECT_BINARY_DIR}/impactbenchConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/impactbench)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/impactbenchConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/impactbenchConfig.cmake
              ${PROJECT_BINARY_DIR}/impactbenchConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/tools/cmake/find_mujoco_ode.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/impactbench)
