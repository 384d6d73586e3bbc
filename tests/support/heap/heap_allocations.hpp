#pragma once
// The number of heap allocations this process has made. Linking this library replaces malloc,
// calloc, realloc and the aligned allocations with counting ones that hand each request to
// glibc: every allocation is counted, operator new's and Eigen's (which calls malloc directly)
// included. Not for a sanitizer build, whose runtime owns malloc.

namespace impactbench::heap {

/// Allocations so far (relaxed atomic reads: exact within one thread).
long allocations();

}  // namespace impactbench::heap
