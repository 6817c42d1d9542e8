#pragma once
// Counts the program's heap allocations: allocation_counter.cpp replaces the global operator
// new, so a test binary that compiles it in (its own binary, as the allocation tests are)
// counts every allocation made after it starts.

namespace impulse2d::testing {

/// Allocations through operator new since the program started.
long allocation_count();

}  // namespace impulse2d::testing
