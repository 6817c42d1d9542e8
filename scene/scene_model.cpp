/// @file scene_model.cpp
#include "scene/scene_model.h"

#include "core/world.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// "circle+box", or "none".
std::string declared_shapes(const SceneModel& model) {
  std::string shapes;
  for (ShapeType type : {ShapeType::Circle, ShapeType::Box, ShapeType::Polygon,
                         ShapeType::Capsule, ShapeType::Segment}) {
    if (model.allows(type))
      shapes += (shapes.empty() ? "" : "+") + std::string(shape_kind_name(type));
  }
  return shapes.empty() ? "none" : shapes;
}

}  // namespace

bool SceneModel::allows(ShapeType type) const {
  switch (type) {
    case ShapeType::Circle:
      return circles;
    case ShapeType::Box:
      return boxes;
    case ShapeType::Polygon:
      return polygons;
    case ShapeType::Capsule:
      return capsules;
    case ShapeType::Segment:
      return segments;
  }
  return false;
}

void apply_model(const SceneModel& model, WorldSettings& settings) {
  if (model.velocity_iterations < 0 || model.position_iterations < 0) {
    throw UsageError("model: velocity_iterations " + std::to_string(model.velocity_iterations) +
                     ", position_iterations " + std::to_string(model.position_iterations) +
                     ": each must be >= 0");
  }
  settings.enable_rotation = model.rotation;
  settings.enable_friction = model.friction;
  settings.enable_restitution = model.restitution;
  settings.enable_continuous = model.ccd;
  settings.enable_sleeping = model.sleeping;
  settings.velocity_iterations = model.velocity_iterations;
  settings.position_iterations = model.position_iterations;
}

void verify_shape_kinds(const SceneModel& model, const World& world,
                        const std::string& scene_name) {
  for (const BodyId id : world.body_ids()) {
    const BodyView view = world.body(id);
    ShapeType type = view.shape->type();
    for (int i = 0; i < view.shape_count && model.allows(type); ++i) type = view.shapes[i].shape.type();
    if (model.allows(type)) continue;
    throw UsageError("scene " + scene_name + ": body " + std::to_string(id.index) + " is a " +
                     shape_kind_name(type) +
                     " but the scene's model declares only " + declared_shapes(model) +
                     " (add it to the model or remove the body)");
  }
}

const char* shape_kind_name(ShapeType type) {
  switch (type) {
    case ShapeType::Circle:
      return "circle";
    case ShapeType::Box:
      return "box";
    case ShapeType::Polygon:
      return "polygon";
    case ShapeType::Capsule:
      return "capsule";
    case ShapeType::Segment:
      return "segment";
  }
  return "unknown";
}

std::string describe_model(const SceneModel& model) {
  auto on_off = [](bool on) { return on ? "on" : "off"; };
  return "shapes " + declared_shapes(model) + ", rotation " + on_off(model.rotation) +
         ", friction " + on_off(model.friction) + ", restitution " + on_off(model.restitution) +
         ", ccd " + on_off(model.ccd) + ", sleeping " + on_off(model.sleeping) + ", iterations " +
         std::to_string(model.velocity_iterations) + "/" +
         std::to_string(model.position_iterations);
}

}  // namespace impulse2d::demos
