#include "core/solver/solver_bodies.h"

#include "core/solver/integrate.h"
#include "core/trig.h"

#include <atomic>

namespace impulse2d {

namespace {
// Body slots a worker takes at least at a time.
constexpr std::size_t min_slots_per_chunk = 256;

// The slots begin, begin + 1, ..., end - 1.
struct SlotRange {
  std::size_t begin;
  std::size_t end;
  std::size_t size() const { return end - begin; }
  std::size_t operator[](std::size_t k) const { return begin + k; }
};

// `count` slots listed at `slots`.
struct SlotList {
  const std::uint32_t* slots;
  std::size_t count;
  std::size_t size() const { return count; }
  std::size_t operator[](std::size_t k) const { return slots[k]; }
};
}  // namespace

void SolverBodies::begin_step(const std::vector<Body>& bodies,
                              const std::vector<std::uint8_t>& alive,
                              const WorldSettings& settings, WorkerPool* pool) {
  states_.resize(bodies.size());
  integration_.resize(bodies.size());
  max_linear_speed_ = settings.max_linear_speed;
  // An OR of the slots' bullet flags: the same whichever worker sets it.
  std::atomic<bool> has_bullets{false};
  parallel_for(pool, bodies.size(), min_slots_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Body& body = bodies[i];
      BodyIntegration& integration = integration_[i];
      integration.flags = 0;
      SolverBody& state = states_[i];
      state.velocity_x = body.linear_velocity.x;
      state.velocity_y = body.linear_velocity.y;
      state.angular_velocity = body.angular_velocity;
      state.angle = body.angle;
      state.position_x = body.transform.position.x;
      state.position_y = body.transform.position.y;
      state.cosine = body.transform.rotation.cosine;
      state.sine = body.transform.rotation.sine;
      if (alive[i] && body.type == BodyType::Dynamic) integration.flags = flag_solved;
      if (!alive[i] || !is_integrated(body)) continue;
      const float inverse_inertia = effective_inverse_inertia(body, settings);
      integration.flags |= flag_moves;
      if (body.type == BodyType::Dynamic) {
        integration.flags |= flag_accelerates;
        const vec2 acceleration =
            body.force * body.inverse_mass + settings.gravity * body.gravity_scale;
        integration.acceleration_x = acceleration.x;
        integration.acceleration_y = acceleration.y;
        integration.angular_acceleration = body.torque * inverse_inertia;
        integration.linear_damping = body.linear_damping;
        integration.angular_damping = body.angular_damping;
      }
      if (body.type != BodyType::Dynamic || inverse_inertia != 0.0f) integration.flags |= flag_turns;
      if (body.is_bullet) has_bullets.store(true, std::memory_order_relaxed);
    }
  });
  has_bullets_ = has_bullets.load(std::memory_order_relaxed);
}

void SolverBodies::integrate_velocities(float dt, WorkerPool* pool) {
  parallel_for(pool, states_.size(), min_slots_per_chunk,
               [&](std::size_t begin, std::size_t end) { integrate_velocities_of(dt, SlotRange{begin, end}); });
}

void SolverBodies::integrate_velocities(float dt, const std::uint32_t* slots, std::size_t count) {
  integrate_velocities_of(dt, SlotList{slots, count});
}

void SolverBodies::integrate_positions(float dt, const std::uint32_t* slots, std::size_t count) {
  integrate_positions_of(dt, SlotList{slots, count});
}

void SolverBodies::integrate_positions(float dt, WorkerPool* pool) {
  parallel_for(pool, states_.size(), min_slots_per_chunk,
               [&](std::size_t begin, std::size_t end) { integrate_positions_of(dt, SlotRange{begin, end}); });
}

template <class Slots>
void SolverBodies::integrate_velocities_of(float dt, Slots slots) {
  const float max_speed_squared = max_linear_speed_ * max_linear_speed_;
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const std::size_t i = slots[k];
    const BodyIntegration& integration = integration_[i];
    if ((integration.flags & flag_accelerates) == 0) continue;
    SolverBody& state = states_[i];
    vec2 velocity(state.velocity_x, state.velocity_y);
    float angular_velocity = state.angular_velocity;
    velocity += vec2(integration.acceleration_x, integration.acceleration_y) * dt;
    angular_velocity += integration.angular_acceleration * dt;
    // Implicit damping, as integrate.cpp.
    velocity *= 1.0f / (1.0f + dt * integration.linear_damping);
    angular_velocity *= 1.0f / (1.0f + dt * integration.angular_damping);
    if ((integration.flags & flag_turns) == 0) angular_velocity = 0.0f;
    const float speed_squared = length_squared(velocity);
    if (speed_squared > max_speed_squared) {
      velocity = clamp_speed(velocity, speed_squared, max_linear_speed_);
    }
    state.velocity_x = velocity.x;
    state.velocity_y = velocity.y;
    state.angular_velocity = angular_velocity;
  }
}

template <class Slots>
void SolverBodies::integrate_positions_of(float dt, Slots slots) {
  // Turned bodies get their cosine and sine four at a time (`cos_sin_4`, bit for bit as
  // `Rotation::from_angle`).
  std::size_t turned[4];
  float angles[4];
  CosSin rotations[4];
  int pending = 0;
  auto rotate_pending = [&] {
    cos_sin_4(angles, rotations);
    for (int k = 0; k < pending; ++k) {
      states_[turned[k]].cosine = rotations[k].cosine;
      states_[turned[k]].sine = rotations[k].sine;
    }
    pending = 0;
  };
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const std::size_t i = slots[k];
    const std::uint32_t flags = integration_[i].flags;
    if ((flags & flag_moves) == 0) continue;
    SolverBody& state = states_[i];
    vec2 position(state.position_x, state.position_y);
    position += vec2(state.velocity_x, state.velocity_y) * dt;
    state.position_x = position.x;
    state.position_y = position.y;
    if ((flags & flag_turns) == 0 || state.angular_velocity == 0.0f) continue;
    state.angle += state.angular_velocity * dt;
    turned[pending] = i;
    angles[pending] = state.angle;
    if (++pending == 4) rotate_pending();
  }
  if (pending == 0) return;
  for (int k = pending; k < 4; ++k) angles[k] = 0.0f;
  rotate_pending();
}

void SolverBodies::store(std::vector<Body>& bodies, WorkerPool* pool) const {
  parallel_for(pool, states_.size(), min_slots_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) store_slot(i, bodies[i]);
  });
}

void SolverBodies::load(const std::vector<Body>& bodies) {
  for (std::size_t i = 0; i < states_.size(); ++i) load_slot(i, bodies[i]);
}

void SolverBodies::store_bodies_of(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                                   const std::vector<std::uint32_t>& listed) const {
  for (const std::uint32_t index : listed) {
    const Contact& contact = contacts[index];
    store_slot(contact.body_a.index, bodies[contact.body_a.index]);
    store_slot(contact.body_b.index, bodies[contact.body_b.index]);
  }
}

void SolverBodies::load_bodies_of(const std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                                  const std::vector<std::uint32_t>& listed) {
  for (const std::uint32_t index : listed) {
    const Contact& contact = contacts[index];
    load_slot(contact.body_a.index, bodies[contact.body_a.index]);
    load_slot(contact.body_b.index, bodies[contact.body_b.index]);
  }
}

void SolverBodies::store_slot(std::size_t slot, Body& body) const {
  const std::uint32_t flags = integration_[slot].flags;
  const SolverBody& state = states_[slot];
  if ((flags & flag_solved) != 0) {
    body.linear_velocity = vec2(state.velocity_x, state.velocity_y);
    body.angular_velocity = state.angular_velocity;
  }
  if ((flags & flag_moves) == 0) return;
  body.angle = state.angle;
  body.transform.position = vec2(state.position_x, state.position_y);
  body.transform.rotation = Rotation{state.cosine, state.sine};
}

void SolverBodies::load_slot(std::size_t slot, const Body& body) {
  const std::uint32_t flags = integration_[slot].flags;
  SolverBody& state = states_[slot];
  if ((flags & flag_solved) != 0) {
    state.velocity_x = body.linear_velocity.x;
    state.velocity_y = body.linear_velocity.y;
    state.angular_velocity = body.angular_velocity;
  }
  if ((flags & flag_moves) == 0) return;
  state.angle = body.angle;
  state.position_x = body.transform.position.x;
  state.position_y = body.transform.position.y;
  state.cosine = body.transform.rotation.cosine;
  state.sine = body.transform.rotation.sine;
}

}  // namespace impulse2d
