#include "core/solver/sleep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse2d {

namespace {

// Bodies a worker takes at least at a time (a few nanoseconds each).
constexpr std::size_t min_bodies_per_chunk = 1024;

}  // namespace

std::uint32_t SleepIslands::find_root(std::uint32_t slot) {
  while (parent_[slot] != slot) {
    parent_[slot] = parent_[parent_[slot]];  // path halving
    slot = parent_[slot];
  }
  return slot;
}

void SleepIslands::update(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                          const std::vector<Contact>& contacts, const std::vector<Joint>& joints,
                          const std::vector<std::uint8_t>& joint_alive,
                          const WorldSettings& settings, float dt, WorkerPool* pool) {
  const std::size_t count = bodies.size();
  const float linear_limit_sq = settings.sleep_linear_speed * settings.sleep_linear_speed;
  parallel_for(pool, count, min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Body& body = bodies[i];
      if (!alive[i] || body.type != BodyType::Dynamic || !body.awake) continue;
      const bool slow = length_squared(body.linear_velocity) <= linear_limit_sq &&
                        std::fabs(body.angular_velocity) <= settings.sleep_angular_speed;
      body.sleep_time = slow ? body.sleep_time + dt : 0.0f;
    }
  });

  parent_.resize(count);
  island_min_slow_.assign(count, std::numeric_limits<float>::infinity());
  for (std::uint32_t i = 0; i < count; ++i) parent_[i] = i;
  for (const Contact& contact : contacts) {
    if (!contact.enabled) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const bool a_dynamic = a.type == BodyType::Dynamic;
    const bool b_dynamic = b.type == BodyType::Dynamic;
    if (a_dynamic && b_dynamic) {
      const std::uint32_t root_a = find_root(contact.body_a.index);
      const std::uint32_t root_b = find_root(contact.body_b.index);
      if (root_a != root_b) parent_[std::max(root_a, root_b)] = std::min(root_a, root_b);
    }
    // A moving kinematic body disturbs what it touches.
    auto is_moving_kinematic = [](const Body& body) {
      return body.type == BodyType::Kinematic &&
             (body.linear_velocity != vec2(0.0f) || body.angular_velocity != 0.0f);
    };
    auto disturb = [](Body& body) {
      body.awake = true;
      body.sleep_time = 0.0f;
    };
    if (is_moving_kinematic(a) && b_dynamic) disturb(b);
    if (is_moving_kinematic(b) && a_dynamic) disturb(a);
  }

  // Jointed bodies share an island (a joint to a static body does not link through it; a
  // moving kinematic body keeps what it is jointed to awake, as a contact does).
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (!joint_alive[j]) continue;
    const Joint& joint = joints[j];
    Body& a = bodies[joint.body_a.index];
    Body& b = bodies[joint.body_b.index];
    if (a.type == BodyType::Dynamic && b.type == BodyType::Dynamic) {
      const std::uint32_t root_a = find_root(joint.body_a.index);
      const std::uint32_t root_b = find_root(joint.body_b.index);
      if (root_a != root_b) parent_[std::max(root_a, root_b)] = std::min(root_a, root_b);
    }
    auto moving_kinematic = [](const Body& body) {
      return body.type == BodyType::Kinematic &&
             (body.linear_velocity != vec2(0.0f) || body.angular_velocity != 0.0f);
    };
    if (moving_kinematic(a) && b.type == BodyType::Dynamic) {
      b.awake = true;
      b.sleep_time = 0.0f;
    }
    if (moving_kinematic(b) && a.type == BodyType::Dynamic) {
      a.awake = true;
      a.sleep_time = 0.0f;
    }
  }

  // Each slot's root, side by side: the forest is only read here (no path halving).
  root_.resize(count);
  parallel_for(pool, count, min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      std::uint32_t slot = static_cast<std::uint32_t>(i);
      while (parent_[slot] != slot) slot = parent_[slot];
      root_[i] = slot;
    }
  });
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!alive[i] || bodies[i].type != BodyType::Dynamic) continue;
    const float slow_time = bodies[i].awake ? bodies[i].sleep_time : settings.time_to_sleep;
    float& island_min = island_min_slow_[root_[i]];
    island_min = std::min(island_min, slow_time);
  }
  parallel_for(pool, count, min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Body& body = bodies[i];
      if (!alive[i] || body.type != BodyType::Dynamic) continue;
      const bool island_rests = island_min_slow_[root_[i]] >= settings.time_to_sleep;
      if (island_rests && body.awake) {
        body.awake = false;
        body.linear_velocity = vec2(0.0f);
        body.angular_velocity = 0.0f;
      } else if (!island_rests && !body.awake) {
        body.awake = true;
        body.sleep_time = 0.0f;
      }
    }
  });
}

}  // namespace impulse2d
