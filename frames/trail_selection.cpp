/// @file trail_selection.cpp
#include "frames/trail_selection.h"

#include <algorithm>
#include <sstream>

#include "core/world.h"
#include "scene/usage_error.h"
#include "render/motion_trails.h"

namespace impulse2d::demos {

TrailSelection parse_trails(const std::string& text, const std::string& option) {
  TrailSelection selection;
  if (text == "dynamic") {
    selection.all_dynamic = true;
    return selection;
  }
  std::stringstream parts(text);
  std::string part;
  while (std::getline(parts, part, ',')) {
    const bool digits = !part.empty() && part.size() <= 9 &&
                        part.find_first_not_of("0123456789") == std::string::npos;
    if (!digits) {
      throw UsageError(option + " '" + text + "': '" + part +
                       "' is not a body index; expected 'dynamic' or indices like 3,7,12 (the "
                       "ids overlay shows them)");
    }
    selection.slots.push_back(static_cast<std::uint32_t>(std::stoul(part)));
  }
  if (selection.slots.empty()) {
    throw UsageError(option + " '" + text + "': expected 'dynamic' or body indices like 3,7,12");
  }
  return selection;
}

void record_trails(const TrailSelection& selection, const World& world, render::MotionTrails& trails) {
  for (const BodyId id : world.body_ids()) {
    const bool chosen = selection.all_dynamic
                            ? world.body(id).type == BodyType::Dynamic
                            : std::find(selection.slots.begin(), selection.slots.end(), id.index) !=
                                  selection.slots.end();
    if (chosen) trails.track(id);
  }
  trails.record(world);
}

}  // namespace impulse2d::demos
