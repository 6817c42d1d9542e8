#include "core/solver/contact_prepare.h"

#include "core/solver/contact_friction_state.h"
#include "core/solver/contact_recycle.h"
#include "core/solver/contact_solver_internal.h"
#include "core/solver/contact_touch.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

using namespace contact_detail;

static_assert(max_manifold_points == 2, "a contact's means over its points halve or keep the sum");

namespace {

// Acceleration (m/s^2) of a body's centre from gravity and applied forces.
vec2 free_acceleration(const Body& body, vec2 gravity) {
  if (body.type != BodyType::Dynamic || !body.awake) return vec2(0.0f);
  return body.force * body.inverse_mass + gravity * body.gravity_scale;
}

}  // namespace

PairMass pair_mass_of(const Body& a, const Body& b, const SolverContext& context) {
  return PairMass{a.inverse_mass, b.inverse_mass, context.rotation ? a.inverse_inertia : 0.0f,
                  context.rotation ? b.inverse_inertia : 0.0f};
}

void set_pair_mass(Contact& contact, const PairMass& mass) {
  const PairMass& old = contact.mass;
  if (!(mass.inverse_mass_a == old.inverse_mass_a && mass.inverse_mass_b == old.inverse_mass_b &&
        mass.inverse_inertia_a == old.inverse_inertia_a && mass.inverse_inertia_b == old.inverse_inertia_b)) {
    contact.kept_masses = false;
  }
  contact.mass = mass;
}

void prepare_contact(Contact& contact, const Body& a, const Body& b, const SolverContext& context) {
  set_pair_mass(contact, pair_mass_of(a, b, context));
  const vec2 normal = contact.normal;
  const vec2 tangent = tangent_of(normal);
  contact.approach_acceleration =
      -glm::dot(free_acceleration(b, context.gravity) - free_acceleration(a, context.gravity), normal);
  // A kept manifold's offsets, and the effective masses found from them, are the same as when
  // it was last prepared (while the masses are too): only its core points move with the bodies.
  const bool keeps_masses = contact.recycled && contact.kept_masses;
  if (!keeps_masses) contact.kept_pair_solve = false;
  const RecycledShapes shapes = recycled_shapes_of(a, b, contact);
  const float rounding = shapes.rounding_a + shapes.rounding_b;
  float slip_sum = 0.0f;
  float load_sum = 0.0f;
  float carried_load = 0.0f;  // N s, before a cold solve drops it
  float slip_need = 0.0f;     // N s, sum over the points of |v_t| m_t
  float fastest_slip = 0.0f;  // m/s
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    point.rounding = rounding;
    if (contact.recycled) {
      if (!keeps_masses) set_recycled_offsets(contact, point);
      set_recycled_cores(a, b, contact, shapes, point);
    } else {
      point.anchor_a = point.point - a.transform.position;
      point.anchor_b = point.point - b.transform.position;
      // Surface points: A's lies depth/2 along +n from the midpoint, B's along -n; the core
      // points a further rounding in.
      const vec2 half_depth = normal * (0.5f * point.depth);
      point.local_anchor_a = core_anchor(a, contact.child_a, point.point + half_depth, normal);
      point.local_anchor_b = core_anchor(b, contact.child_b, point.point - half_depth, -normal);
    }
    const vec2 velocity = relative_velocity(a, b, point);
    const float slip = glm::dot(velocity, tangent);
    slip_sum += slip;
    point.caught = -glm::dot(velocity, normal) > context.catch_speed;
    if (!keeps_masses) {
      const float k_normal = inverse_effective_mass(contact.mass, point, normal);
      const float k_tangent = inverse_effective_mass(contact.mass, point, tangent);
      point.normal_mass = k_normal > 0.0f ? 1.0f / k_normal : 0.0f;
      point.tangent_mass = k_tangent > 0.0f ? 1.0f / k_tangent : 0.0f;
    }
    fastest_slip = std::max(fastest_slip, std::fabs(slip));
    slip_need += std::fabs(slip) * point.tangent_mass;
    carried_load += point.normal_impulse;
    point.velocity_bias = 0.0f;
    point.bouncing = false;
    point.waiting = false;
    point.bounce_speed = 0.0f;
    if (!context.warm_starting) {
      point.normal_impulse = 0.0f;
      point.tangent_impulse = 0.0f;
    }
    if (!context.friction) point.tangent_impulse = 0.0f;
    load_sum += point.normal_impulse;
  }
  contact.kept_masses = contact.recycled;
  // The means over the points: halving is exact, so it gives the bits dividing by 2 gives.
  const bool two_points = contact.point_count == 2;
  contact.start_slip = two_points ? slip_sum * 0.5f : slip_sum;
  contact.start_load = load_sum;
  // Surfaces already slipping faster than static friction can stop within the step slide from
  // its start, whatever set them moving (contact_friction_state.h).
  if (context.friction_intervals > 0.0f && !contact.sliding && fastest_slip > sticking_speed &&
      static_friction_cannot_stop(two_points ? slip_need * 0.5f : slip_need, carried_load,
                                  contact.static_friction, context.friction_intervals)) {
    break_loose(contact);
  }
  if (context.touch_velocities.linear != nullptr) {
    contact.touching = touches_in_step(context.touch_velocities, contact, context.slop, context.time_step);
  }
}

void prepare_contacts(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                      const SolverContext& context) {
  for (Contact& contact : contacts) {
    if (!contact.enabled) continue;
    prepare_contact(contact, bodies[contact.body_a.index], bodies[contact.body_b.index], context);
  }
}

void warm_start_contacts(const std::vector<Contact>& contacts, std::vector<Body>& bodies) {
  for (const Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const vec2 tangent = tangent_of(contact.normal);
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      apply_impulse(a, b, contact.mass, point,
                    contact.normal * point.normal_impulse + tangent * point.tangent_impulse);
    }
  }
}

}  // namespace impulse2d
