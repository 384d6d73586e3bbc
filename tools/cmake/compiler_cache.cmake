# ccache (Debian package ccache) when installed: a rebuild after a branch switch, a second preset
# or a fresh clone on the same machine compiles only what changed. CCACHE_BASEDIR makes the
# cached commands relative to this checkout, so clones in other folders share the cache.
find_program(IMPACTBENCH_CCACHE ccache)
if(IMPACTBENCH_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  # pch_defines,time_macros: what ccache needs to cache files built with a precompiled header.
  set(launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true
               CCACHE_SLOPPINESS=pch_defines,time_macros
               ${IMPACTBENCH_CCACHE})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
  set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
endif()
