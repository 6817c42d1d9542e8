#pragma once
/// @file contact_bounce.h
/// Non-penetration targets of a (sub-)step, with restitution timed at the moment of impact.
///
/// Each point may close its gap g (m) within the step of h seconds, and no more: the solve
/// keeps its relative normal velocity vn >= -g / h (a speculative contact), or >= 0 once
/// touching. A point whose approach speed v (m/s, before the solve) exceeds the restitution
/// threshold and whose gap closes within this step bounces. Semi-implicit Euler moves
/// positions with the end-of-step velocity, so within the step the gap closes at
/// tau = g / v; the impact speed, with the closing acceleration a (gravity, forces) over the
/// step, is u = v + a (tau - h/2); afterwards the point separates at e u. The solve therefore
/// targets vn = e u - (1 + e) g / h, which leaves the point e (v h - g) apart at the end of
/// the step (where the reflected motion puts it), and after positions move its velocity is
/// raised to e u - a (h/2 - tau) (the reflected speed at the step's velocity instant).
/// Measured: apexes of a dropped ball within 0.2 % of e^(2k) h0 at 60 Hz (tests/test_bounce).

#include "core/solver/body_state.h"
#include "core/contact.h"
#include "core/solver/solver_context.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// How a point bounces in one (sub-)step, from `plan_bounce`.
struct BouncePlan {
  bool bouncing = false;    ///< false: no bounce in this step (too slow, or the gap stays open)
  float solve_speed = 0.0f; ///< m/s: target relative normal velocity of the velocity solve
  float leave_speed = 0.0f; ///< m/s: separating speed once positions have moved
};

/// The bounce of a point approaching at `approach_speed` (m/s, > 0 closing) across `gap`
/// metres (<= 0: touching or overlapping) with closing acceleration `approach_acceleration`
/// (m/s^2), restitution `restitution`, over a step of `h` seconds; no bounce at or below
/// `threshold` m/s.
BouncePlan plan_bounce(float approach_speed, float gap, float approach_acceleration,
                       float restitution, float threshold, float h);

/// What the bounce plans ask before they read or change a contact's accumulated impulses, or
/// change its plan: a solver that keeps the impulses elsewhere while it runs (the soft step's
/// lanes) writes that contact's out, and reads back in exactly the contacts written out. The
/// plans' other callers keep the contacts current and pass none.
class ContactWriteOut {
 public:
  virtual ~ContactWriteOut() = default;
  /// Writes the accumulated impulses of contact `index` (of the list) out to it, unless they
  /// were written out since the last read-back: a plan may ask twice, and may have changed
  /// them in between.
  virtual void write_out(std::uint32_t index) = 0;
};

/// The first half of `plan_contact_speeds`: each elastic point's bounce (`bouncing`,
/// `bounce_speed`, and a bouncing point's `velocity_bias`), after dropping the impulses of a
/// point whose bounce was applied in an earlier sub-step (`ContactPoint::bounced`); marks the
/// bodies that bounce in `bouncing_bodies` and lists the contacts in `bouncing_contacts`.
/// Reads no impulse but those it drops. Returns true when some point bounces. With a
/// `write_out`, it is asked for every contact with a point that has bounced, bounces or waits
/// (an earlier sub-step's plan), before anything of it changes.
bool plan_bounces(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                  const SolverContext& context, float h, bool bounces_only,
                  std::vector<std::uint8_t>& bouncing_bodies,
                  std::vector<std::uint32_t>& bouncing_contacts,
                  ContactWriteOut* write_out = nullptr);

/// The second half of `plan_contact_speeds`, after `plan_bounces`: clears every point's
/// `waiting`, then marks the points that wait beside a bounce (reading their normal impulses)
/// and, without `bounces_only`, sets the other points' speculative targets. With a
/// `write_out`, it is asked for every elastic contact beside a bounce (the bouncing contacts
/// among them) before its impulses are read; a contact whose wait ends was asked for by
/// `plan_bounces`.
void plan_waits(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                const SolverContext& context, float h, bool bounces_only,
                const std::vector<std::uint8_t>& bouncing_bodies,
                ContactWriteOut* write_out = nullptr);

/// Sets every point's `velocity_bias` for a (sub-)step of `h` seconds from its current gap
/// (recomputed from the transforms) and relative velocity: -gap/h while apart, 0 when
/// touching, or a bounce from `plan_bounce`; an elastic point on a body that bounces in this
/// step that neither approaches, overlaps nor carries last step's impulse is marked `waiting`
/// (left out of the solve). With `bounces_only`, points that do not bounce
/// are left as they are (the soft solver computes their targets itself).
/// `bouncing_bodies` is scratch (one flag per body slot, reused between calls);
/// `bouncing_contacts` is set to the indices of the contacts with a bouncing point, in the
/// list's order (what `apply_bounces` visits). Returns true when some point bounces (without
/// one, `apply_bounces` has nothing to do).
bool plan_contact_speeds(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                         const SolverContext& context, float h, bool bounces_only,
                         std::vector<std::uint8_t>& bouncing_bodies,
                         std::vector<std::uint32_t>& bouncing_contacts);

/// After positions moved: raises every bouncing point's relative normal velocity to its
/// `bounce_speed` (accumulated impulse kept >= 0) in Gauss-Seidel passes over the bouncing
/// points, so that simultaneous bounces are met together, both points of a manifold at once
/// (2x2 block); then ends the bounces. `bouncing_contacts` lists the contacts with a bouncing
/// point in the list's order, as `plan_contact_speeds` found them (the passes visit only
/// those).
void apply_bounces(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                   const std::vector<std::uint32_t>& bouncing_contacts);

/// Current separation (m) of a prepared point, from its core anchors: > 0 apart. Inline: the
/// soft step asks it for every point in every pass.
inline float current_separation(const Body& a, const Body& b, const Contact& contact,
                                const ContactPoint& point) {
  const vec2 core_a = a.transform.apply(point.local_anchor_a);
  const vec2 core_b = b.transform.apply(point.local_anchor_b);
  return glm::dot(core_b - core_a, contact.normal) - point.rounding;
}

}  // namespace impulse2d
