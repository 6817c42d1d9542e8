// The stages of a step over one world's state (`SolverStages`, step_solver.h), each timed into
// its stats.
#include "core/solver/step_solver.h"

#include "core/collide/narrow_phase.h"
#include "core/collide/speculative_reach.h"
#include "core/solver/integrate.h"
#include "core/solver/position_correction.h"

#include <algorithm>
#include <chrono>

namespace impulse2d {

namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

bool is_moving(const Body& body) { return body.type != BodyType::Static && body.awake; }

// Moves the contacts of `from` that `leaves` selects into `into`, both lists staying in pair
// order (a merge through `scratch`); the others stay in `from`, in order.
template <class Leaves>
void move_contacts(std::vector<Contact>& from, std::vector<Contact>& into,
                   std::vector<Contact>& scratch, Leaves leaves) {
  scratch.clear();
  std::size_t stayed = 0;
  std::size_t merged = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    if (!leaves(from[i])) {
      if (stayed != i) from[stayed] = from[i];
      ++stayed;
      continue;
    }
    while (merged < into.size() && contact_less(into[merged], from[i])) scratch.push_back(into[merged++]);
    scratch.push_back(from[i]);
  }
  if (stayed == from.size()) return;
  scratch.insert(scratch.end(), into.begin() + static_cast<std::ptrdiff_t>(merged), into.end());
  std::swap(into, scratch);
  from.erase(from.begin() + static_cast<std::ptrdiff_t>(stayed), from.end());
}

// Removes from `pairs` (ascending) every pair in `unconnected` (ascending keys a << 32 | b):
// bodies joined by a joint without `collide_connected` never make contacts. One merge walk.
void drop_jointed_pairs(const std::vector<std::uint64_t>& unconnected, std::vector<BodyPair>& pairs) {
  std::size_t key = 0;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::uint64_t pair_key = static_cast<std::uint64_t>(pairs[i].first) << 32 | pairs[i].second;
    while (key < unconnected.size() && unconnected[key] < pair_key) ++key;
    if (key < unconnected.size() && unconnected[key] == pair_key) continue;
    pairs[kept++] = pairs[i];
  }
  pairs.resize(kept);
}

}  // namespace

// Last step's contacts whose bodies no longer move would be dropped by the narrow phase (no
// broad-phase pair has them); they are set aside instead, impulses and all, in pair order.
// Set-aside contacts of pairs that move again go back among last step's contacts, so the
// narrow phase carries their impulses over (warm start) as if they had never slept.
void SolverStages::set_aside_sleeping_contacts() {
  // A contact rests only when both its bodies do, so with no body asleep (and none set aside)
  // there is nothing to move: skip the two walks over the contacts.
  bool any_asleep = false;
  for (std::size_t i = 0; i < world_.bodies.size() && !any_asleep; ++i) {
    const Body& body = world_.bodies[i];
    any_asleep = world_.alive[i] && body.type != BodyType::Static && !body.awake;
  }
  if (!any_asleep && world_.sleeping_contacts.empty()) return;
  // The scratch and set-aside lists hold no more contacts than the step list has room for;
  // grown with it during warm-up, the first bodies to fall asleep later allocate nothing.
  const std::size_t capacity = world_.contacts.capacity();
  if (world_.merged_contacts.capacity() < capacity) world_.merged_contacts.reserve(capacity);
  if (world_.sleeping_contacts.capacity() < capacity) world_.sleeping_contacts.reserve(capacity);
  auto resting = [this](const Contact& contact) {
    return !is_moving(world_.bodies[contact.body_a.index]) &&
           !is_moving(world_.bodies[contact.body_b.index]);
  };
  move_contacts(world_.sleeping_contacts, world_.contacts, world_.merged_contacts,
                [&resting](const Contact& contact) { return !resting(contact); });
  move_contacts(world_.contacts, world_.sleeping_contacts, world_.merged_contacts, resting);
}

void SolverStages::find_contacts(float dt, ContactVisitor* visitor) {
  Clock::time_point stage = Clock::now();
  set_aside_sleeping_contacts();
  // Bounds are current after a step, `create_body` and `set_transform`; from here to the end
  // of the step the stages move bodies, so they count as stale (a sub-step's next call
  // remakes them).
  if (!world_.bounds_current) update_bounds(world_.bodies, world_.alive, pool_);
  world_.bounds_current = false;
  compute_speculative_reach(world_.bodies, world_.alive, world_.settings, dt,
                            world_.speculative_reach, pool_);
  compute_speculative_bounds(world_.bodies, world_.alive, world_.speculative_reach,
                             world_.settings.speculative_margin, world_.speculative_bounds, pool_);
  world_.broad_phase.find_pairs(world_.bodies, world_.alive, world_.speculative_bounds,
                                world_.settings.broad_phase, world_.pairs, pool_);
  if (!world_.unconnected_pairs.empty()) drop_jointed_pairs(world_.unconnected_pairs, world_.pairs);
  world_.stats.broad_phase_ms += elapsed_ms(stage);

  stage = Clock::now();
  world_.stats.contact_point_count =
      update_contacts(world_.bodies, world_.pairs, world_.speculative_reach, world_.settings, dt,
                      world_.contact_filter, world_.contacts, world_.spilled_contacts, visitor, pool_,
                      &world_.narrow_jobs);
  world_.stats.pairs_tested = static_cast<int>(world_.pairs.size());
  world_.stats.contact_count = static_cast<int>(world_.contacts.size());
  world_.stats.sleeping_contact_count = static_cast<int>(world_.sleeping_contacts.size());
  world_.stats.narrow_phase_ms += elapsed_ms(stage);
}

void SolverStages::integrate_velocities(float dt) {
  const Clock::time_point stage = Clock::now();
  impulse2d::integrate_velocities(world_.bodies, world_.alive, world_.settings, dt, pool_);
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::integrate_positions(float dt) {
  const Clock::time_point stage = Clock::now();
  impulse2d::integrate_positions(world_.bodies, world_.alive, world_.settings, dt, pool_);
  if (world_.settings.enable_continuous) {
    world_.stats.bullets_moved_back += world_.bullet_sweeper.sweep(
        world_.bodies, world_.alive, world_.settings, dt, world_.broad_phase);  // no tunnelling
  }
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::prepare_joints(float h, bool clear_impulses) {
  impulse2d::prepare_joints(world_.joints, world_.joint_alive, world_.bodies, world_.settings, h,
                            clear_impulses);
}

void SolverStages::begin_solver_bodies() {
  const Clock::time_point stage = Clock::now();
  world_.solver_body_states.begin_step(world_.bodies, world_.alive, world_.settings, pool_);
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::integrate_solver_velocities(float dt) {
  const Clock::time_point stage = Clock::now();
  world_.solver_body_states.integrate_velocities(dt, pool_);
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::integrate_solver_positions(float dt) {
  const Clock::time_point stage = Clock::now();
  world_.solver_body_states.integrate_positions(dt, pool_);
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::sweep_bullets(float dt) {
  if (!world_.settings.enable_continuous) return;
  const Clock::time_point stage = Clock::now();
  world_.stats.bullets_moved_back += world_.bullet_sweeper.sweep(
      world_.bodies, world_.alive, world_.settings, dt, world_.broad_phase);
  world_.stats.integrate_ms += elapsed_ms(stage);
}

void SolverStages::correct_positions() {
  const Clock::time_point stage = Clock::now();
  switch (world_.settings.position_correction) {
    case PositionCorrection::None: break;
    case PositionCorrection::LinearProjection:
      correct_positions_linear(world_.contacts, world_.bodies, world_.settings);
      break;
    case PositionCorrection::NonlinearGaussSeidel:
      correct_positions_nonlinear(world_.contacts, world_.bodies, world_.settings);
      break;
  }
  world_.stats.position_ms += elapsed_ms(stage);
}

}  // namespace impulse2d
