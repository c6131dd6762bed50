#include "allocation_counter.h"

#include <cstdlib>
#include <new>

namespace {
long g_allocations = 0;
}  // namespace

// Replacing the global operator new (and its matching deletes) counts every allocation of
// the binary; this object file is linked whenever a test calls allocationCount().
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace ncc::test {

long allocationCount() { return g_allocations; }

}  // namespace ncc::test
