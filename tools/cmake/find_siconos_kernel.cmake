# Optional, never required, off unless IMPACTBENCH_WITH_SICONOS_ENGINE: the Siconos kernel
# (Debian libsiconos-kernel-dev, which brings
# libsiconos-numerics-dev) for `--engine siconos`. Found: the target impactbench_siconos_kernel
# exists and IMPACTBENCH_HAVE_SICONOS_ENGINE is ON; not found: the engine is listed but refused
# as not built. Like Siconos Numerics (dependencies.cmake), the headers and libraries are looked
# up directly: Debian's siconos-config.cmake imports components the packages do not ship.
set(IMPACTBENCH_HAVE_SICONOS_ENGINE OFF)
if(IMPACTBENCH_WITH_SICONOS_ENGINE)
  find_path(SICONOS_KERNEL_INCLUDE_DIR siconos/kernel/SiconosKernel.hpp)
  find_library(SICONOS_KERNEL_LIBRARY siconos_kernel)
  find_library(SICONOS_NUMERICS_LIBRARY siconos_numerics)
  if(SICONOS_KERNEL_INCLUDE_DIR AND SICONOS_KERNEL_LIBRARY AND SICONOS_NUMERICS_LIBRARY)
    set(IMPACTBENCH_HAVE_SICONOS_ENGINE ON)
    add_library(impactbench_siconos_kernel INTERFACE IMPORTED)
    # The kernel's headers include each other and the numerics headers by bare name.
    set(siconos_root ${SICONOS_KERNEL_INCLUDE_DIR}/siconos)
    target_include_directories(impactbench_siconos_kernel SYSTEM INTERFACE
      ${siconos_root} ${siconos_root}/kernel ${siconos_root}/numerics)
    target_link_libraries(impactbench_siconos_kernel INTERFACE
      ${SICONOS_KERNEL_LIBRARY} ${SICONOS_NUMERICS_LIBRARY})
    message(STATUS "Siconos kernel found (${SICONOS_KERNEL_LIBRARY}): building --engine siconos")
  else()
    message(STATUS "Siconos kernel not found: --engine siconos is not built (optional)")
  endif()
endif()
