#pragma once
/// @file scene_model.h
/// What a scene needs from the physics: "model no more than a scene needs". A scene declares
/// its model; running it turns off everything else in `WorldSettings` and checks that the
/// built world keeps to the declared shape kinds.

#include <cstdint>
#include <string>

#include "core/settings.h"
#include "core/shape.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// The physics a scene uses.
struct SceneModel {
  bool circles = false;     ///< uses circle shapes
  bool boxes = false;       ///< uses axis-aligned (never rotating) boxes
  bool polygons = false;    ///< uses convex polygons (including oriented boxes and rounded ones)
  bool capsules = false;    ///< uses capsules
  bool segments = false;    ///< uses segments (static and kinematic bodies only)
  bool rotation = true;     ///< bodies spin (angular terms solved and integrated)
  bool friction = true;     ///< tangent impulses solved
  bool restitution = true;  ///< contacts may bounce
  bool ccd = false;         ///< bodies marked `is_bullet` are swept so they cannot tunnel

  bool sleeping = false;        ///< bodies at rest are put to sleep
  int velocity_iterations = WorldSettings{}.velocity_iterations;  ///< solver passes per step
  int position_iterations = WorldSettings{}.position_iterations;  ///< position-correction passes per step (NGS only)

  /// True when the model declares shapes of kind `type`.
  bool allows(ShapeType type) const;
};

/// Sets the model switches of `settings`: rotation, friction, restitution, continuous
/// collision, sleeping and the iteration counts. Throws `UsageError` for negative iteration
/// counts.
void apply_model(const SceneModel& model, WorldSettings& settings);

/// Throws `UsageError` naming the scene, the first offending body slot and its shape kind when
/// a living body of `world` has a shape kind the model does not declare.
void verify_shape_kinds(const SceneModel& model, const World& world, const std::string& scene_name);

/// "circle" / "box" / "polygon" / "capsule" / "segment".
const char* shape_kind_name(ShapeType type);

/// One line: "shapes circle+box, rotation off, friction on, restitution on, ccd off,
/// sleeping off, iterations 16/3".
std::string describe_model(const SceneModel& model);

}  // namespace impulse2d::demos
