# The Python module `impactbench` (tools/python): ON by default when Debian's pybind11
# (pybind11-dev) is found, built for Debian's /usr/bin/python3 (a pyenv python3 first on PATH
# cannot see Debian's numpy). Off by default under the sanitizers: an ASan-built module loads
# into /usr/bin/python3 only with libasan preloaded (LD_PRELOAD), and LeakSanitizer then reports
# CPython's and numpy's own allocations at exit, so the Python tests would need leak detection
# off and would check less than the sanitizer tests of the code they call (the library and the
# program, which the module shares); the sanitizer preset also keeps its objects non-PIC.
if(EXISTS /usr/bin/python3 AND NOT DEFINED PYTHON_EXECUTABLE)
  set(PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python the module is built for")
endif()
find_package(pybind11 CONFIG QUIET)  # pybind11-dev
set(python_default OFF)
if(pybind11_FOUND AND NOT IMPACTBENCH_SANITIZE)
  set(python_default ON)
endif()
option(IMPACTBENCH_BUILD_PYTHON "Build the Python module (pybind11)" ${python_default})
# Where the package goes below the prefix (the build tree mirrors it); PYTHONPATH names it.
set(IMPACTBENCH_PYTHON_INSTALL_DIR "lib/python3/dist-packages" CACHE STRING
    "Folder of the Python package below the install prefix")
if(IMPACTBENCH_BUILD_PYTHON)
  if(NOT pybind11_FOUND)
    find_package(pybind11 CONFIG REQUIRED)
  endif()
  message(STATUS "pybind11 ${pybind11_VERSION} found: building the Python module")
else()
  message(STATUS "Python module not built (pybind11-dev not found, IMPACTBENCH_BUILD_PYTHON off, "
                 "or the sanitizer build)")
endif()
