#include "core/solver/contact_bounce.h"

#include "core/solver/contact_solver_internal.h"
#include "core/solver/normal_block_solve.h"

#include <algorithm>

namespace impulse2d {

using namespace contact_detail;

namespace {

// Gauss-Seidel passes that raise the bounces of a step together (whatever the solver's own
// iteration count: Box2D v3's one pass a sub-step would leave two hits on one body unshared).
// Sixteen keep an elastic gas's energy within 1e-5 over a minute (tests/test_contact_pairs).
constexpr int bounce_passes = 16;

// Target speed (m/s) of a waiting point: so far below any real velocity that the clamped
// impulse stays 0, yet finite so the block solver's arithmetic stays finite.
constexpr float waiting_target_speed = -1.0e9f;

// Drops the accumulated impulses of a point whose bounce was applied in an earlier sub-step,
// so the collision's impulse is not warm-started as if it were a resting load (across steps
// the narrow phase does not carry it over).
void forget_bounce(ContactPoint& point) {
  if (!point.bounced) return;
  point.normal_impulse = 0.0f;
  point.tangent_impulse = 0.0f;
  point.bounced = false;
}

// True when some point of the contact has bounced, bounces or waits: a plan of an earlier
// sub-step that the next plan changes.
bool has_bounce_plan(const Contact& contact) {
  for (int i = 0; i < contact.point_count; ++i) {
    const ContactPoint& point = contact.points[i];
    if (point.bounced || point.bouncing || point.waiting) return true;
  }
  return false;
}

}  // namespace

BouncePlan plan_bounce(float approach_speed, float gap, float approach_acceleration,
                       float restitution, float threshold, float h) {
  BouncePlan plan;
  const float open_gap = std::max(gap, 0.0f);
  if (!(restitution > 0.0f && approach_speed > threshold)) return plan;
  if (!(open_gap < approach_speed * h)) return plan;  // the gap stays open this step
  const float impact_time = open_gap / approach_speed;
  const float impact_speed =
      std::max(approach_speed + approach_acceleration * (impact_time - 0.5f * h), 0.0f);
  plan.bouncing = true;
  plan.solve_speed = restitution * impact_speed - (1.0f + restitution) * open_gap / h;
  plan.leave_speed = restitution * impact_speed - approach_acceleration * (0.5f * h - impact_time);
  return plan;
}

bool plan_bounces(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                  const SolverContext& context, float h, bool bounces_only,
                  std::vector<std::uint8_t>& bouncing_bodies,
                  std::vector<std::uint32_t>& bouncing_contacts, ContactWriteOut* write_out) {
  bouncing_bodies.assign(bodies.size(), 0);
  bouncing_contacts.clear();
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    Contact& contact = contacts[index];
    if (!is_solvable(contact)) continue;
    const bool may_bounce = context.restitution && contact.restitution > 0.0f;
    if (bounces_only && !may_bounce) continue;
    const Body& a = bodies[contact.body_a.index];
    const Body& b = bodies[contact.body_b.index];
    // (A contact that bounces now is asked for by plan_waits: its bodies bounce.)
    if (write_out != nullptr && has_bounce_plan(contact)) {
      write_out->write_out(static_cast<std::uint32_t>(index));
    }
    bool contact_bounces = false;
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      forget_bounce(point);
      BouncePlan plan;
      const float approach_speed =
          may_bounce ? -glm::dot(relative_velocity(a, b, point), contact.normal) : 0.0f;
      // At or below the threshold plan_bounce plans none whatever the gap: it is not found.
      if (may_bounce && approach_speed > context.restitution_threshold) {
        plan = plan_bounce(approach_speed, current_separation(a, b, contact, point),
                           contact.approach_acceleration, contact.restitution,
                           context.restitution_threshold, h);
      }
      point.bouncing = plan.bouncing;
      point.bounce_speed = plan.leave_speed;
      if (plan.bouncing) {
        contact_bounces = true;
        point.velocity_bias = plan.solve_speed;
        bouncing_bodies[contact.body_a.index] = 1;
        bouncing_bodies[contact.body_b.index] = 1;
      }
    }
    if (contact_bounces) bouncing_contacts.push_back(static_cast<std::uint32_t>(index));
  }
  return !bouncing_contacts.empty();
}

void plan_waits(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                const SolverContext& context, float h, bool bounces_only,
                const std::vector<std::uint8_t>& bouncing_bodies, ContactWriteOut* write_out) {
  const float inverse_h = 1.0f / h;
  // An elastic point beside a bounce that neither approaches, overlaps beyond the slop nor
  // carries impulse waits; the rest get their speculative target.
  for (std::size_t index = 0; index < contacts.size(); ++index) {
    Contact& contact = contacts[index];
    if (!is_solvable(contact)) continue;
    const bool may_bounce = context.restitution && contact.restitution > 0.0f;
    if (bounces_only && !may_bounce) continue;
    const Body& a = bodies[contact.body_a.index];
    const Body& b = bodies[contact.body_b.index];
    const bool beside_bounce =
        bouncing_bodies[contact.body_a.index] != 0 || bouncing_bodies[contact.body_b.index] != 0;
    if (write_out != nullptr && may_bounce && beside_bounce) {
      write_out->write_out(static_cast<std::uint32_t>(index));
    }
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      point.waiting = false;
      if (point.bouncing) continue;
      const bool may_wait = may_bounce && beside_bounce;
      if (bounces_only && !may_wait) continue;  // its target is the soft solver's
      const float gap = current_separation(a, b, contact, point);
      if (may_wait) {
        // Does not reach its surface within this step at the velocities the step began with:
        // if the bounce beside drives it in, it collides (and bounces) next step, instead of
        // being stopped inelastically inside this solve.
        const float approach_speed = -glm::dot(relative_velocity(a, b, point), contact.normal);
        const bool closes = approach_speed > 0.0f && approach_speed * h > std::max(gap, 0.0f);
        point.waiting = gap >= -context.slop && !closes && point.normal_impulse == 0.0f;
      }
      if (point.waiting) {
        point.velocity_bias = waiting_target_speed;
      } else if (!bounces_only) {
        point.velocity_bias = gap > 0.0f ? -gap * inverse_h : 0.0f;
      }
    }
  }
}

bool plan_contact_speeds(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                         const SolverContext& context, float h, bool bounces_only,
                         std::vector<std::uint8_t>& bouncing_bodies,
                         std::vector<std::uint32_t>& bouncing_contacts) {
  const bool bounces =
      plan_bounces(contacts, bodies, context, h, bounces_only, bouncing_bodies, bouncing_contacts);
  plan_waits(contacts, bodies, context, h, bounces_only, bouncing_bodies);
  return bounces;
}

void apply_bounces(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                   const std::vector<std::uint32_t>& bouncing_contacts) {
  // Gauss-Seidel passes over the bouncing points only, each pass meeting every bounce's target
  // in turn with accumulated impulses (kept >= 0): the bounces of one step converge together,
  // as the velocity solve's constraints do, so two hits on one body share it as the exact
  // simultaneous answer does. The two points of a manifold that both bounce are met at once
  // (the 2x2 block), so a box landing flat leaves flat.
  for (int pass = 0; pass < bounce_passes; ++pass) {
    bool any_bounce = false;
    for (const std::uint32_t index : bouncing_contacts) {  // solvable: the plan listed them
      Contact& contact = contacts[index];
      Body& a = bodies[contact.body_a.index];
      Body& b = bodies[contact.body_b.index];
      int bouncing = 0;
      for (int i = 0; i < contact.point_count; ++i) bouncing += contact.points[i].bouncing ? 1 : 0;
      if (bouncing == 0) continue;
      any_bounce = true;
      if (bouncing == 2) {
        ContactPoint* points = contact.points;
        const float solve_targets[2] = {points[0].velocity_bias, points[1].velocity_bias};
        points[0].velocity_bias = points[0].bounce_speed;
        points[1].velocity_bias = points[1].bounce_speed;
        const bool solved = solve_normal_block(a, b, contact, contact.mass);
        points[0].velocity_bias = solve_targets[0];
        points[1].velocity_bias = solve_targets[1];
        if (solved) continue;
      }
      for (int i = 0; i < contact.point_count; ++i) {
        ContactPoint& point = contact.points[i];
        if (point.bouncing) push_normal_to(a, b, contact, point, point.bounce_speed);
      }
    }
    if (!any_bounce) return;
  }
  for (const std::uint32_t index : bouncing_contacts) {
    Contact& contact = contacts[index];
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      if (!point.bouncing) continue;
      point.bouncing = false;
      point.bounced = true;
    }
  }
}

}  // namespace impulse2d
