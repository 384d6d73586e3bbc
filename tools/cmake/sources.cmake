# impactbench_glob(<var> <dir>...): the C++ sources below each folder, re-globbed on every build
# so that a new file is picked up without editing CMake.
function(impactbench_glob out)
  set(result "")
  foreach(dir IN LISTS ARGN)
    file(GLOB_RECURSE found CONFIGURE_DEPENDS "${dir}/*.cpp")
    list(APPEND result ${found})
  endforeach()
  set(${out} ${result} PARENT_SCOPE)
endfunction()
