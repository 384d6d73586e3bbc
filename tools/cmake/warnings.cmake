# Project-wide warning and sanitizer flags, applied through an interface target.
add_library(impactbench_flags INTERFACE)
# Warnings are ours: a program built against the installed package does not inherit them.
target_compile_options(impactbench_flags INTERFACE
  $<BUILD_INTERFACE:-Wall -Wextra -Wpedantic -Wshadow=local>)
if(IMPACTBENCH_SANITIZE)
  target_compile_options(impactbench_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                     -fno-sanitize-recover=undefined)
  target_link_options(impactbench_flags INTERFACE -fsanitize=address,undefined)
endif()
