#pragma once
/// @file trail_selection.h
/// Which bodies leave motion trails in rendered frames (`impulse2d render --trails`).

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d {
class World;
}

namespace impulse2d::render {
class MotionTrails;
}

namespace impulse2d::demos {

/// The bodies whose recent path is drawn.
struct TrailSelection {
  bool all_dynamic = false;           ///< every dynamic body, including ones spawned later
  std::vector<std::uint32_t> slots;   ///< body slot indices (as the `ids` overlay shows them)
  /// True when no body is selected.
  bool empty() const { return !all_dynamic && slots.empty(); }
};

/// Parses `dynamic` or comma-separated body indices (`3,7,12`). Throws `UsageError` naming
/// `option` and the bad part.
TrailSelection parse_trails(const std::string& text, const std::string& option);

/// Starts tracking every living body the selection names that `trails` does not track yet
/// (bodies can appear during a run), then records each tracked body's position.
void record_trails(const TrailSelection& selection, const World& world, render::MotionTrails& trails);

}  // namespace impulse2d::demos
