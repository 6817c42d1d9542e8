#pragma once
/// @file body_shapes.h
/// A body's shapes in the world: its one shape under its transform, or each shape of a compound
/// body under its transform composed with the shape's placement. Every part of the step that
/// looks at geometry (bounds, narrow phase, sensors, queries, continuous collision, drawing)
/// walks a body's shapes through these.

#include "core/collide.h"
#include "core/solver/body_state.h"

namespace impulse2d {

/// Number of shapes `body` has (1 unless compound).
inline int shape_count_of(const Body& body) {
  return body.compound ? static_cast<int>(body.children.size()) : 1;
}

/// `body`'s shape `child` (its one shape when not compound).
inline const Shape& shape_of(const Body& body, int child) {
  return body.compound ? body.children[static_cast<std::size_t>(child)].shape : body.shape;
}

/// Where `body`'s shape `child` lies in the world when the body stands at `transform`.
inline Transform shape_transform(const Body& body, int child, const Transform& transform) {
  return body.compound ? compose(transform, body.children[static_cast<std::size_t>(child)].local)
                       : transform;
}

/// Where `body`'s shape `child` lies in the world now.
inline Transform shape_transform(const Body& body, int child) {
  return shape_transform(body, child, body.transform);
}

/// The collision layers of `body`'s shape `child` (the body's when not compound).
inline std::uint32_t layers_of(const Body& body, int child) {
  return body.compound ? body.children[static_cast<std::size_t>(child)].collision_layers
                       : body.collision_layers;
}

/// True when `body`'s shape `child` is a sensor shape of a compound body (a sensor body's
/// shapes are sensors through `Body::is_sensor`).
inline bool is_sensor_shape(const Body& body, int child) {
  return body.compound && body.children[static_cast<std::size_t>(child)].is_sensor;
}

/// The material of `body`'s shape `child` (the body's when not compound).
inline const Material& material_of(const Body& body, int child) {
  return body.compound ? body.children[static_cast<std::size_t>(child)].material : body.material;
}

/// World bounds of all of `body`'s shapes with the body at `transform`.
inline Aabb body_aabb(const Body& body, const Transform& transform) {
  if (!body.compound) return compute_aabb(body.shape, transform);
  Aabb bounds = compute_aabb(body.children[0].shape, compose(transform, body.children[0].local));
  for (std::size_t i = 1; i < body.children.size(); ++i) {
    const Aabb part = compute_aabb(body.children[i].shape, compose(transform, body.children[i].local));
    bounds.lower = glm::min(bounds.lower, part.lower);
    bounds.upper = glm::max(bounds.upper, part.upper);
  }
  return bounds;
}

/// World bounds of all of `body`'s shapes now.
inline Aabb body_aabb(const Body& body) { return body_aabb(body, body.transform); }

/// True when a shape of `a`, with `a` standing at `at_a`, overlaps a shape of `b` whose layers
/// it shares (the narrow phase's test at margin 0).
inline bool bodies_overlap(const Body& a, const Transform& at_a, const Body& b) {
  if (!a.compound && !b.compound) return collide(a.shape, at_a, b.shape, b.transform).point_count > 0;
  for (int i = 0; i < shape_count_of(a); ++i) {
    const Transform placed_a = shape_transform(a, i, at_a);
    if (is_sensor_shape(a, i)) continue;
    for (int k = 0; k < shape_count_of(b); ++k) {
      if ((layers_of(a, i) & layers_of(b, k)) == 0 || is_sensor_shape(b, k)) continue;
      if (collide(shape_of(a, i), placed_a, shape_of(b, k), shape_transform(b, k)).point_count > 0) return true;
    }
  }
  return false;
}

/// True when the world point lies inside (or on) one of `body`'s shapes.
inline bool body_contains_point(const Body& body, vec2 point) {
  for (int i = 0; i < shape_count_of(body); ++i) {
    if (shape_contains_point(shape_of(body, i), shape_transform(body, i), point)) return true;
  }
  return false;
}

/// Casts the segment `origin` -> `origin + translation` against those of `body`'s shapes whose
/// layers share a bit with `layers` (its sensor shapes only with `sensors`); true with the
/// first entry of any of them in `hit`.
inline bool raycast_body(const Body& body, vec2 origin, vec2 translation, std::uint32_t layers,
                         bool sensors, ShapeRayHit* hit) {
  bool found = false;
  for (int i = 0; i < shape_count_of(body); ++i) {
    if ((layers_of(body, i) & layers) == 0 || (!sensors && is_sensor_shape(body, i))) continue;
    ShapeRayHit part;
    if (raycast_shape(shape_of(body, i), shape_transform(body, i), origin, translation, &part) &&
        (!found || part.fraction < hit->fraction)) {
      *hit = part;
      found = true;
    }
  }
  return found;
}

/// Mass (kg), area, centre of mass (body frame, metres) and inertia about it (kg m^2) of
/// `shapes`, each at its own material's density: the sums over the shapes, the inertias moved
/// to the common centre by the parallel axis theorem.
MassData compound_mass(const std::vector<BodyShape>& shapes);

/// After a compound body's shapes or materials changed: for a dynamic body, moves its origin to
/// the new centre of mass (the shapes stay where they are in the world) and sets its mass and
/// inertia; for every body, its extent, layers (the union of its shapes') and bounds.
void recentre_compound(Body& body);

}  // namespace impulse2d
