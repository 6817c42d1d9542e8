/// @file scene_helpers.cpp
#include "demos/scene_helpers.h"

#include <array>
#include <cmath>

#include "core/world.h"

namespace impulse2d::demos {

BodyId add_body(World& world, BodyType type, const Shape& shape, vec2 position,
                const Material& material, float angle, std::uint32_t layers) {
  BodyDef def;
  def.type = type;
  def.position = position;
  def.angle = angle;
  def.material = material;
  def.collision_layers = layers;
  return world.create_body(def, shape);
}

BodyId add_static_box(World& world, vec2 center, vec2 half_extents, const Material& material,
                      std::uint32_t layers) {
  return add_body(world, BodyType::Static, make_box(half_extents), center, material, 0.0f, layers);
}

Shape random_convex_polygon(SceneRandom& random, float radius) {
  const int count = random.integer(3, max_polygon_vertices);
  const float sector = 6.28318530718f / static_cast<float>(count);
  std::array<vec2, max_polygon_vertices> vertices{};
  for (int i = 0; i < count; ++i) {
    const float angle = (static_cast<float>(i) + random.uniform(0.15f, 0.85f)) * sector;
    vertices[static_cast<std::size_t>(i)] = radius * Rotation::from_angle(angle).x_axis();
  }
  return make_polygon(vertices.data(), count);
}

Material frictionless(Material material) {
  material.name += " (frictionless)";
  material.static_friction = 0.0f;
  material.dynamic_friction = 0.0f;
  return material;
}

Aabb make_bounds(vec2 lower, vec2 upper) {
  Aabb box;
  box.lower = lower;
  box.upper = upper;
  return box;
}

float radians(float degrees) { return degrees * 0.0174532925199f; }

}  // namespace impulse2d::demos
