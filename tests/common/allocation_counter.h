#pragma once
// Counts heap allocations of the whole test binary: linking ncc_test_allocation_counter
// replaces the global operator new. Real-time paths (VM tick, servo step, planner) are tested
// to allocate nothing after construction by comparing the count before and after.

namespace ncc::test {

// Allocations through operator new since the program started.
long allocationCount();

}  // namespace ncc::test
