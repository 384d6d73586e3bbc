# Project-wide warning and sanitizer flags, applied through an interface target.
add_library(impactbench_flags INTERFACE)
target_compile_options(impactbench_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow=local)
if(IMPACTBENCH_SANITIZE)
  target_compile_options(impactbench_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                     -fno-sanitize-recover=undefined)
  target_link_options(impactbench_flags INTERFACE -fsanitize=address,undefined)
endif()
