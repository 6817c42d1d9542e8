#pragma once
/// @file scene_joint_reader.h
/// Reading one joint object of a scene file (`joints[i]`, or a `create_joint` event's
/// `joint`) into a `JointSpec`, with path-precise errors and warnings.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "scene/json_cursor.h"
#include "scene/scene_event.h"

namespace impulse2d::demos {

/// What the joint reader may know about the scene's bodies.
struct JointBodies {
  /// Body name -> creation index.
  const std::map<std::string, int>* names = nullptr;
  /// Creation indices that can be named: [0, count).
  int count = 0;
  /// The body of a creation index as the file declares it (for the anchor warning and the
  /// static body a mouse joint holds on to), or nullptr when unknown.
  std::function<const BodySpawn*(int)> spawn;
};

/// Reads a joint object. Throws `UsageError` "<file>: <path>: <reason>" for an unknown type
/// or field, an unknown body (`joints[2].bodies[1]: unknown body "armm"`), a body jointed to
/// itself, reversed limits, a zero axis, a number out of its range. Appends to `warnings`
/// ("<file>: <path>: ...") an anchor that lies far outside both of its bodies as declared.
JointSpec read_joint(const JsonCursor& node, const JointBodies& bodies, std::vector<std::string>& warnings,
                     const std::string& file);

}  // namespace impulse2d::demos
