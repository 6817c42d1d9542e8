// Compound bodies: one body of several shapes, each placed in the body's frame with its own
// material and layers; the body's mass, centre of mass and inertia are the shapes' summed
// about their common centre (parallel axis theorem).
#include "core/error.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <cmath>
#include <string>

namespace impulse2d {

namespace {

std::string shape_path(int index) { return "World::create_body: shapes[" + std::to_string(index) + "]"; }

// The placed shape for `def`: a `Box` (which never turns with its body) becomes the polygon
// of the same outline, which does.
Shape placed_shape(const Shape& shape) {
  if (shape.type() == ShapeType::Box) return make_oriented_box(shape.box().half_extents);
  if (shape.type() != ShapeType::Polygon) return shape;
  Polygon polygon = shape.polygon();
  polygon.radius = farthest_vertex_distance(polygon);  // not trusted from the caller
  return polygon;
}

}  // namespace

MassData compound_mass(const std::vector<BodyShape>& shapes) {
  MassData total;
  vec2 moment{0.0f, 0.0f};  // kg m: sum of mass times centroid
  for (const BodyShape& part : shapes) {
    const MassData mass = compute_mass(part.shape, part.material.density);
    total.mass += mass.mass;
    total.area += mass.area;
    moment += mass.mass * part.local.apply(mass.centroid);
  }
  if (!(total.mass > 0.0f)) return total;
  total.centroid = moment / total.mass;
  for (const BodyShape& part : shapes) {
    const MassData mass = compute_mass(part.shape, part.material.density);
    total.inertia += mass.inertia + mass.mass * length_squared(part.local.apply(mass.centroid) - total.centroid);
  }
  return total;
}

void recentre_compound(Body& body) {
  const MassData mass = compound_mass(body.children);
  if (body.type == BodyType::Dynamic) {
    for (BodyShape& part : body.children) part.local.position -= mass.centroid;
    body.transform.position = body.transform.apply(mass.centroid);
    body.previous_position = body.transform.position;
    body.mass = mass.mass;
    body.inverse_mass = 1.0f / mass.mass;
    body.inertia = mass.inertia;
    body.inverse_inertia = (!body.fixed_rotation && mass.inertia > 0.0f) ? 1.0f / mass.inertia : 0.0f;
  }
  body.extent = 0.0f;
  body.collision_layers = 0;
  for (const BodyShape& part : body.children) {
    const vec2 at = part.local.position;
    body.extent = std::max(body.extent, std::sqrt(length_squared(at)) + shape_extent(part.shape));
    body.collision_layers |= part.collision_layers;
  }
  body.shape = body.children[0].shape;
  body.rounding = 0.0f;  // per shape: `rounding_of`
  body.aabb = body_aabb(body);
}

BodyId World::create_body(const BodyDef& def, const ShapeDef* shapes, int count) {
  if (count < 1 || count > max_body_shapes || shapes == nullptr) {
    throw Error("World::create_body: a body takes 1.." + std::to_string(max_body_shapes) +
                " shapes (got " + std::to_string(count) + (shapes ? ")" : " and no array)"));
  }
  std::vector<BodyShape> parts(static_cast<std::size_t>(count));
  bool has_area = false;
  for (int i = 0; i < count; ++i) {
    const ShapeDef& given = shapes[i];
    const std::string path = shape_path(i);
    validate_shape(given.shape, path);
    if (!(is_finite(given.position) && std::isfinite(given.angle))) {
      throw Error(path + ": position and angle must be finite");
    }
    if (given.shape.type() == ShapeType::Segment && given.shape.segment().one_sided) {
      throw Error(path + ": a chain link cannot be part of a body (use World::create_chain)");
    }
    validate_material(given.material, path + ": material");
    const bool area = given.shape.type() != ShapeType::Segment;
    if (def.type == BodyType::Dynamic && area && !(given.material.density > 0.0f)) {
      throw Error(path + ": a dynamic body's shapes need material density > 0 (got " +
                  std::to_string(given.material.density) + ")");
    }
    has_area = has_area || area;
    BodyShape& part = parts[static_cast<std::size_t>(i)];
    part.shape = placed_shape(given.shape);
    part.local = Transform{given.position, Rotation::from_angle(given.angle)};
    part.material = given.material;
    part.collision_layers = given.collision_layers;
    part.is_sensor = given.is_sensor;
  }
  if (def.type == BodyType::Dynamic && !has_area) {
    throw Error("World::create_body: a dynamic body needs a shape with area (all its shapes are "
                "segments: make it static or kinematic, or add a capsule or polygon)");
  }
  // The body is made as one of its shapes would be (every check of `def` there), then given
  // all of them.
  BodyDef first = def;
  first.material = parts[0].material;
  if (def.type == BodyType::Dynamic && parts[0].shape.type() == ShapeType::Segment) {
    first.material.density = 1.0f;  // the segment's mass is replaced below
  }
  const Shape stand_in = parts[0].shape.type() == ShapeType::Segment ? make_circle(1.0f) : parts[0].shape;
  const BodyId id = create_body(first, stand_in);
  Body& body = state_->bodies[id.index];
  body.compound = true;
  body.children = std::move(parts);
  recentre_compound(body);
  for (const BodyShape& part : body.children) body.has_sensor_shapes = body.has_sensor_shapes || part.is_sensor;
  // Counted as a sensor (its events are collected) once; the body was counted without its shapes.
  if (body.has_sensor_shapes && !body.is_sensor) ++state_->events.sensor_bodies;
  state_->broad_phase.cover(id.index, body.aabb);
  return id;
}

}  // namespace impulse2d
