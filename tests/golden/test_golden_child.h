#pragma once
/// @file test_golden_child.h
/// A golden's frame produced in a child process (this test binary run again with a filter
/// and environment variables), for the checks that compare processes: thread counts and
/// cross-process determinism.

#include <map>
#include <string>

#include "golden/check_run.h"
#include "golden/scenes/golden_run.h"

namespace impulse2d::golden::testing {

/// Scene variants a child can apply, by name (the child gets the name, not the code).
enum class ChildVariant {
  None,
  /// Gravity depends on the process id: identical within a process, different between two
  /// processes, like a value derived from an address under ASLR.
  ProcessDependentGravity,
};

/// The variant itself (nullptr for None).
SceneVariant child_variant(ChildVariant variant);

/// A producer that runs golden `id` in a child process with the extra environment
/// `variables` and `variant`, and returns its image and state hash (no bodies or samples).
/// Throws `std::runtime_error` when the child fails.
FrameProducer child_process_producer(const std::string& id,
                                     const std::map<std::string, std::string>& variables = {},
                                     ChildVariant variant = ChildVariant::None);

}  // namespace impulse2d::golden::testing
