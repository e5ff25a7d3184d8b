#pragma once
// Counts global operator new calls, so tests can assert that right-hand sides and table
// evaluations allocate nothing. Replaces the global operator new/delete: include this header in
// exactly ONE source file of a test executable. The replacement pairs malloc/free on purpose.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#include <atomic>
#include <cstdlib>
#include <new>

namespace rbtest {
inline std::atomic<long> g_allocations{0};
// Allocations since the program started; compare before/after the code under test.
inline long allocationCount() {
  return g_allocations.load();
}
}  // namespace rbtest

void* operator new(std::size_t n) {
  ++rbtest::g_allocations;
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
