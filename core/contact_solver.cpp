#include "core/contact_solver.h"

#include "core/contact_solver_internal.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

using namespace contact_detail;

namespace {

// Solves both normal impulses of a 2-point manifold at once: find x >= 0 with
// v = K x + b >= 0 and x . v = 0 (a 2x2 linear complementarity problem) by trying the four
// cases in turn, where K is the 2x2 effective-mass matrix and b the velocities without the
// accumulated impulses. Returns false (solve point by point instead) when K is ill-conditioned.
bool solve_normal_block(Body& a, Body& b, const PairMass& mass, Contact& contact) {
  ContactPoint& p1 = contact.points[0];
  ContactPoint& p2 = contact.points[1];
  const vec2 normal = contact.normal;
  const float arm_a1 = cross(p1.anchor_a, normal), arm_b1 = cross(p1.anchor_b, normal);
  const float arm_a2 = cross(p2.anchor_a, normal), arm_b2 = cross(p2.anchor_b, normal);
  const float linear = mass.inverse_mass_a + mass.inverse_mass_b;
  const float k11 = linear + mass.inverse_inertia_a * arm_a1 * arm_a1 + mass.inverse_inertia_b * arm_b1 * arm_b1;
  const float k22 = linear + mass.inverse_inertia_a * arm_a2 * arm_a2 + mass.inverse_inertia_b * arm_b2 * arm_b2;
  const float k12 = linear + mass.inverse_inertia_a * arm_a1 * arm_a2 + mass.inverse_inertia_b * arm_b1 * arm_b2;
  const float determinant = k11 * k22 - k12 * k12;
  constexpr float max_condition = 1000.0f;
  if (!(k11 * k11 < max_condition * determinant)) return false;

  const vec2 old_impulse{p1.normal_impulse, p2.normal_impulse};
  const float speed1 = glm::dot(relative_velocity(a, b, p1), normal) - p1.velocity_bias;
  const float speed2 = glm::dot(relative_velocity(a, b, p2), normal) - p2.velocity_bias;
  const vec2 rhs{speed1 - (k11 * old_impulse.x + k12 * old_impulse.y),
                 speed2 - (k12 * old_impulse.x + k22 * old_impulse.y)};
  vec2 impulse;
  // Case 1: both points push. x = -K^-1 b.
  impulse = vec2(-(k22 * rhs.x - k12 * rhs.y), -(-k12 * rhs.x + k11 * rhs.y)) / determinant;
  if (!(impulse.x >= 0.0f && impulse.y >= 0.0f)) {
    // Case 2: only the first pushes; the second must then be separating.
    impulse = vec2(-rhs.x / k11, 0.0f);
    if (!(impulse.x >= 0.0f && k12 * impulse.x + rhs.y >= 0.0f)) {
      // Case 3: only the second pushes.
      impulse = vec2(0.0f, -rhs.y / k22);
      if (!(impulse.y >= 0.0f && k12 * impulse.y + rhs.x >= 0.0f)) {
        // Case 4: neither pushes; both must be separating already.
        impulse = vec2(0.0f);
        if (!(rhs.x >= 0.0f && rhs.y >= 0.0f)) return false;
      }
    }
  }
  apply_impulse(a, b, mass, p1, normal * (impulse.x - old_impulse.x));
  apply_impulse(a, b, mass, p2, normal * (impulse.y - old_impulse.y));
  p1.normal_impulse = impulse.x;
  p2.normal_impulse = impulse.y;
  return true;
}

}  // namespace

void prepare_contacts(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                      const WorldSettings& settings) {
  const bool keep_impulses = settings.solver != SolverMethod::PerIteration && settings.warm_starting;
  for (Contact& contact : contacts) {
    if (!contact.enabled) continue;
    const Body& a = bodies[contact.body_a.index];
    const Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const vec2 normal = contact.normal;
    const vec2 tangent = tangent_of(normal);
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      point.anchor_a = point.point - a.transform.position;
      point.anchor_b = point.point - b.transform.position;
      // Surface points: A's lies depth/2 along +n from the midpoint, B's along -n.
      const vec2 half_depth = normal * (0.5f * point.depth);
      point.local_anchor_a = a.transform.apply_inverse(point.point + half_depth);
      point.local_anchor_b = b.transform.apply_inverse(point.point - half_depth);
      const float k_normal = inverse_effective_mass(mass, point, normal);
      const float k_tangent = inverse_effective_mass(mass, point, tangent);
      point.normal_mass = k_normal > 0.0f ? 1.0f / k_normal : 0.0f;
      point.tangent_mass = k_tangent > 0.0f ? 1.0f / k_tangent : 0.0f;
      const float approach = glm::dot(relative_velocity(a, b, point), normal);
      point.velocity_bias = 0.0f;
      if (settings.enable_restitution && approach < -settings.restitution_threshold) {
        point.velocity_bias = -contact.restitution * approach;
      }
      if (!keep_impulses) {
        point.normal_impulse = 0.0f;
        point.tangent_impulse = 0.0f;
      }
      if (!settings.enable_friction) point.tangent_impulse = 0.0f;
    }
  }
}

void warm_start_contacts(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const WorldSettings& settings) {
  for (const Contact& contact : contacts) {
    if (!is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const vec2 tangent = tangent_of(contact.normal);
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      apply_impulse(a, b, mass, point, contact.normal * point.normal_impulse + tangent * point.tangent_impulse);
    }
  }
}

void solve_contacts_accumulated(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                const WorldSettings& settings) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const vec2 normal = contact.normal;
    if (settings.enable_friction) solve_friction_points(a, b, mass, contact);

    if (settings.block_solver && contact.point_count == 2 &&
        solve_normal_block(a, b, mass, contact)) {
      continue;
    }
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      const float normal_speed = glm::dot(relative_velocity(a, b, point), normal);
      const float accumulated =
          std::max(point.normal_impulse - (normal_speed - point.velocity_bias) * point.normal_mass, 0.0f);
      const float change = accumulated - point.normal_impulse;
      point.normal_impulse = accumulated;
      apply_impulse(a, b, mass, point, normal * change);
    }
  }
}

void solve_contacts_per_iteration(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                  const WorldSettings& settings) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const vec2 normal = contact.normal;
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      const float normal_speed = glm::dot(relative_velocity(a, b, point), normal);
      if (normal_speed > 0.0f) continue;  // separating: this point needs nothing (others may)
      // e (1 + e) form: the restitution target velocity_bias equals -e * approach speed.
      const float normal_impulse = -(normal_speed - point.velocity_bias) * point.normal_mass;
      apply_impulse(a, b, mass, point, normal * normal_impulse);
      point.normal_impulse = normal_impulse;

      if (!settings.enable_friction) continue;
      const vec2 velocity = relative_velocity(a, b, point);
      const vec2 tangential = velocity - normal * glm::dot(velocity, normal);
      const float tangential_speed = glm::length(tangential);
      if (tangential_speed <= 0.0f) continue;
      const vec2 tangent = tangential / tangential_speed;
      const float k_tangent = inverse_effective_mass(mass, point, tangent);
      if (k_tangent <= 0.0f) continue;
      const float sticking_impulse = -tangential_speed / k_tangent;
      float friction_impulse = sticking_impulse;
      point.sliding = std::fabs(sticking_impulse) >= normal_impulse * contact.static_friction;
      if (point.sliding) friction_impulse = -normal_impulse * contact.dynamic_friction;
      apply_impulse(a, b, mass, point, tangent * friction_impulse);
      // Stored in the fixed tangent frame so drawing and statistics read one convention.
      point.tangent_impulse = friction_impulse * glm::dot(tangent, tangent_of(normal));
    }
  }
}

void break_static_friction(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                           const WorldSettings& settings) {
  if (!settings.enable_friction) return;
  for (Contact& contact : contacts) {
    if (!is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const vec2 tangent = tangent_of(contact.normal);
    // The manifold breaks loose only when every point's friction is at its static limit: one
    // saturated point alone just shifts load to the other (a box on a slope).
    bool all_at_static_limit = true;
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      all_at_static_limit = all_at_static_limit && !point.sliding && point.friction_at_limit;
    }
    if (!all_at_static_limit) continue;
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      point.sliding = true;
      const float dynamic_limit = contact.dynamic_friction * point.normal_impulse;
      const float accumulated = point.tangent_impulse < 0.0f ? -dynamic_limit : dynamic_limit;
      apply_impulse(a, b, mass, point, tangent * (accumulated - point.tangent_impulse));
      point.tangent_impulse = accumulated;
    }
  }
}

void update_sliding_state(std::vector<Contact>& contacts, const std::vector<Body>& bodies) {
  for (Contact& contact : contacts) {
    if (!contact.enabled) continue;
    const Body& a = bodies[contact.body_a.index];
    const Body& b = bodies[contact.body_b.index];
    const vec2 tangent = tangent_of(contact.normal);
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      const bool moving = std::fabs(glm::dot(relative_velocity(a, b, point), tangent)) > sticking_speed;
      point.sliding = moving || (point.sliding && point.friction_at_limit);
    }
  }
}

}  // namespace impulse2d
