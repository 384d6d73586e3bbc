#include "tests/support/heap/heap_allocations.hpp"

#include <atomic>
#include <cerrno>
#include <cstddef>

namespace {

std::atomic<long> counted{0};

void count() {
  counted.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace

namespace impactbench::heap {

long allocations() {
  return counted.load(std::memory_order_relaxed);
}

}  // namespace impactbench::heap

// Defined in the executable, these take the place of glibc's for the whole process (shared
// libraries included); glibc's own entry points do the work.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  count();
  return __libc_malloc(size);
}
void* calloc(std::size_t count_of, std::size_t size) {
  count();
  return __libc_calloc(count_of, size);
}
void* realloc(void* p, std::size_t size) {
  count();
  return __libc_realloc(p, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  count();
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** p, std::size_t alignment, std::size_t size) {
  count();
  *p = __libc_memalign(alignment, size);
  return *p != nullptr || size == 0 ? 0 : ENOMEM;
}
}
