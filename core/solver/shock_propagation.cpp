#include "core/solver/shock_propagation.h"

#include "core/solver/contact_solver_internal.h"
#include "core/solver/normal_block_solve.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

using namespace contact_detail;

namespace {

// A contact supports when its normal is within 45 degrees of the vertical.
constexpr float min_support_cosine = 0.70710678f;

// True when the contact is part of the support graph (see build_support_order).
bool supports(const Contact& contact, vec2 up) {
  if (!is_solvable(contact)) return false;
  if (std::fabs(glm::dot(contact.normal, up)) < min_support_cosine) return false;
  bool pushes = false;
  for (int i = 0; i < contact.point_count; ++i) {
    const ContactPoint& point = contact.points[i];
    if (point.bouncing || point.waiting) return false;
    pushes = pushes || point.normal_impulse > 0.0f;
  }
  return pushes;
}

// True when both bodies have a level and the one nearer the ground lies below the other (the
// normal points from A to B, so B is on top when it points up).
bool lower_is_below(const Contact& contact, vec2 up, const std::vector<int>& level) {
  const int level_a = level[contact.body_a.index];
  const int level_b = level[contact.body_b.index];
  if (level_a < 0 || level_b < 0 || level_a == level_b) return false;
  const bool b_on_top = glm::dot(contact.normal, up) > 0.0f;
  return b_on_top == (level_a < level_b);
}

// The contact's body on top (the normal points from A to B, so B is on top when it points up).
std::uint32_t upper_body(const Contact& contact, vec2 up) {
  return glm::dot(contact.normal, up) > 0.0f ? contact.body_b.index : contact.body_a.index;
}

// The contact's body below.
std::uint32_t lower_body(const Contact& contact, vec2 up) {
  return glm::dot(contact.normal, up) > 0.0f ? contact.body_a.index : contact.body_b.index;
}

// True when the body on top is heavier than the one below by more than `mass_ratio`.
bool heavy_on_light(const Contact& contact, vec2 up, const std::vector<Body>& bodies,
                    float mass_ratio) {
  return bodies[lower_body(contact, up)].inverse_mass >
         mass_ratio * bodies[upper_body(contact, up)].inverse_mass;
}

// The level of the contact's body nearer the ground.
int lower_level(const Contact& contact, const std::vector<int>& level) {
  return std::min(level[contact.body_a.index], level[contact.body_b.index]);
}

// `mass` with the body at `level_a` or `level_b` nearer the ground made immovable.
PairMass with_lower_fixed(PairMass mass, int level_a, int level_b) {
  if (level_a < level_b) {
    mass.inverse_mass_a = 0.0f;
    mass.inverse_inertia_a = 0.0f;
  } else {
    mass.inverse_mass_b = 0.0f;
    mass.inverse_inertia_b = 0.0f;
  }
  return mass;
}

// Accumulated normal update of one point through `mass` (push_normal_to with another mass).
void push_normal_with(Body& a, Body& b, const Contact& contact, ContactPoint& point,
                      const PairMass& mass) {
  const float k = inverse_effective_mass(mass, point, contact.normal);
  if (!(k > 0.0f)) return;
  const float normal_speed = glm::dot(relative_velocity(a, b, point), contact.normal);
  const float accumulated =
      std::max(point.normal_impulse - (normal_speed - point.velocity_bias) / k, 0.0f);
  const float change = accumulated - point.normal_impulse;
  point.normal_impulse = accumulated;
  apply_impulse(a, b, mass, point, contact.normal * change);
}

// Accumulated Coulomb friction of one contact through `mass` (solve_friction_points with
// another mass).
void friction_with(Body& a, Body& b, Contact& contact, const PairMass& mass) {
  const vec2 tangent = tangent_of(contact.normal);
  const float coefficient = contact.sliding ? contact.dynamic_friction : contact.static_friction;
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const float k = inverse_effective_mass(mass, point, tangent);
    if (!(k > 0.0f)) continue;
    const float tangent_speed = glm::dot(relative_velocity(a, b, point), tangent);
    const float limit = coefficient * point.normal_impulse;
    const float accumulated = std::clamp(point.tangent_impulse - tangent_speed / k, -limit, limit);
    const float change = accumulated - point.tangent_impulse;
    point.tangent_impulse = accumulated;
    apply_impulse(a, b, mass, point, tangent * change);
  }
}

}  // namespace

float shock_mass_ratio(int velocity_iterations) {
  constexpr float ln2 = 0.69314718f;
  return static_cast<float>(velocity_iterations) / ln2;
}

bool is_heavy_on_light(const Contact& contact, float mass_ratio) {
  if (!is_solvable(contact)) return false;
  const float inverse_mass_a = contact.mass.inverse_mass_a;
  const float inverse_mass_b = contact.mass.inverse_mass_b;
  return (inverse_mass_a > mass_ratio * inverse_mass_b && inverse_mass_b > 0.0f) ||
         (inverse_mass_b > mass_ratio * inverse_mass_a && inverse_mass_a > 0.0f);
}

void build_support_order(const std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                         vec2 gravity, int velocity_iterations, bool same_contacts,
                         SupportOrder& order) {
  const float g = glm::length(gravity);
  if (!(g > 0.0f)) {
    order.contacts_upward.clear();
    order.supporting.clear();
    return;
  }
  const vec2 up = -gravity / g;
  const float mass_ratio = shock_mass_ratio(velocity_iterations);
  // Which contacts support, asked once of each (the passes below read it four times).
  order.next_supporting.resize(contacts.size());
  bool needs_order = false;
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    const bool supporting = supports(contacts[index], up);
    order.next_supporting[index] = supporting ? 1 : 0;
    needs_order =
        needs_order || (supporting && heavy_on_light(contacts[index], up, bodies, mass_ratio));
  }
  // The rest depends only on which contacts support, the contacts and the bodies' masses.
  if (same_contacts && order.next_supporting == order.supporting) return;
  std::swap(order.supporting, order.next_supporting);
  order.contacts_upward.clear();
  // Most steps have no heavy-on-light pair at all: then there is no chain to order.
  if (!needs_order) return;
  const int slots = static_cast<int>(bodies.size());
  order.level.assign(bodies.size(), -1);
  order.edge_start.assign(bodies.size() + 1, 0);
  order.queue.clear();
  // Adjacency in compressed rows: count each body's supporting contacts, then fill.
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    if (order.supporting[index] == 0) continue;
    const Contact& contact = contacts[index];
    ++order.edge_start[contact.body_a.index + 1];
    ++order.edge_start[contact.body_b.index + 1];
  }
  for (int slot = 0; slot < slots; ++slot) order.edge_start[slot + 1] += order.edge_start[slot];
  order.edge_body.resize(static_cast<std::size_t>(order.edge_start[slots]));
  order.queue.assign(order.edge_start.begin(), order.edge_start.end() - 1);  // fill cursors
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    if (order.supporting[index] == 0) continue;
    const Contact& contact = contacts[index];
    const int a = static_cast<int>(contact.body_a.index);
    const int b = static_cast<int>(contact.body_b.index);
    order.edge_body[order.queue[a]++] = b;
    order.edge_body[order.queue[b]++] = a;
  }
  // Breadth-first from every fixed body with an edge.
  order.queue.clear();
  for (int slot = 0; slot < slots; ++slot) {
    if (bodies[slot].inverse_mass == 0.0f && order.edge_start[slot + 1] > order.edge_start[slot]) {
      order.level[slot] = 0;
      order.queue.push_back(slot);
    }
  }
  int deepest = 0;
  for (std::size_t head = 0; head < order.queue.size(); ++head) {
    const int body = order.queue[head];
    for (int edge = order.edge_start[body]; edge < order.edge_start[body + 1]; ++edge) {
      const int next = order.edge_body[edge];
      if (order.level[next] >= 0) continue;
      order.level[next] = order.level[body] + 1;
      deepest = std::max(deepest, order.level[next]);
      order.queue.push_back(next);
    }
  }
  // Counting sort of the supporting contacts between levels by the level of their lower body.
  order.level_count.assign(static_cast<std::size_t>(deepest) + 2, 0);
  int between_levels = 0;
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    const Contact& contact = contacts[index];
    if (order.supporting[index] == 0 || !lower_is_below(contact, up, order.level)) continue;
    ++order.level_count[lower_level(contact, order.level) + 1];
    ++between_levels;
  }
  for (int level = 0; level <= deepest; ++level) order.level_count[level + 1] += order.level_count[level];
  order.queue.resize(static_cast<std::size_t>(between_levels));
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    const Contact& contact = contacts[index];
    if (order.supporting[index] == 0 || !lower_is_below(contact, up, order.level)) continue;
    order.queue[order.level_count[lower_level(contact, order.level)]++] = static_cast<int>(index);
  }
  // From the top down: a contact takes part when it is heavy-on-light or its upper body rests
  // (through contacts that take part) under one; then its lower body does too.
  order.under_heavy.assign(bodies.size(), 0);
  for (auto it = order.queue.rbegin(); it != order.queue.rend(); ++it) {
    const Contact& contact = contacts[*it];
    if (order.under_heavy[upper_body(contact, up)] != 0 ||
        heavy_on_light(contact, up, bodies, mass_ratio)) {
      order.under_heavy[lower_body(contact, up)] = 1;
      order.contacts_upward.push_back(*it);
    }
  }
  std::reverse(order.contacts_upward.begin(), order.contacts_upward.end());
}

void solve_shock_pass(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                      const SupportOrder& order, bool block_solver, bool friction) {
  for (const int index : order.contacts_upward) {
    Contact& contact = contacts[index];
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = with_lower_fixed(contact.mass, order.level[contact.body_a.index],
                                           order.level[contact.body_b.index]);
    float kept_normal[max_manifold_points];
    float kept_tangent[max_manifold_points];
    for (int i = 0; i < contact.point_count; ++i) {
      kept_normal[i] = contact.points[i].normal_impulse;
      kept_tangent[i] = contact.points[i].tangent_impulse;
    }
    if (!(block_solver && contact.point_count == 2 && solve_normal_block(a, b, contact, mass))) {
      for (int i = 0; i < contact.point_count; ++i) push_normal_with(a, b, contact, contact.points[i], mass);
    }
    if (friction) friction_with(a, b, contact, mass);
    for (int i = 0; i < contact.point_count; ++i) {
      contact.points[i].normal_impulse = kept_normal[i];
      contact.points[i].tangent_impulse = kept_tangent[i];
    }
  }
}

}  // namespace impulse2d
