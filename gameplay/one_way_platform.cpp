#include "gameplay/one_way_platform.h"

#include "core/error.h"

#include <cmath>

namespace impulse2d {

void OneWayPlatforms::add(BodyId platform, vec2 up) {
  if (platform.is_null()) throw Error("OneWayPlatforms::add: platform is a null handle");
  if (!(is_finite(up) && std::abs(glm::length(up) - 1.0f) < 1.0e-3f)) {
    throw Error("OneWayPlatforms::add: up must be a unit vector");
  }
  for (Platform& existing : platforms_) {
    if (existing.body == platform) {
      existing.up = up;
      return;
    }
  }
  platforms_.push_back(Platform{platform, up});
}

const OneWayPlatforms::Platform* OneWayPlatforms::find(BodyId body) const {
  for (const Platform& platform : platforms_) {
    if (platform.body == body) return &platform;
  }
  return nullptr;
}

bool OneWayPlatforms::contains(BodyId body) const { return find(body) != nullptr; }

bool OneWayPlatforms::allows(const BodyView& a, const BodyView& b, const Manifold& manifold) const {
  const Platform* platform = find(a.id);
  const bool platform_is_a = platform != nullptr;
  if (!platform_is_a) platform = find(b.id);
  if (platform == nullptr) return true;
  const BodyView& platform_body = platform_is_a ? a : b;
  const BodyView& other = platform_is_a ? b : a;

  const vec2 up = platform_body.transform.rotation.rotate(platform->up);
  const vec2 normal_to_other = platform_is_a ? manifold.normal : -manifold.normal;
  if (glm::dot(normal_to_other, up) < cos_sin(max_normal_angle).cosine) return false;

  // Velocity of the platform's material under the other body (it may move and turn).
  vec2 contact_point = other.transform.position;
  if (manifold.point_count > 0) contact_point = manifold.points[0].point;
  const vec2 platform_velocity =
      platform_body.linear_velocity +
      cross(platform_body.angular_velocity, contact_point - platform_body.transform.position);
  const float rising_speed = glm::dot(other.linear_velocity - platform_velocity, up);
  return rising_speed <= rising_speed_tolerance;
}

ContactFilter OneWayPlatforms::filter(ContactFilter next) const {
  return [this, next = std::move(next)](const BodyView& a, const BodyView& b, const Manifold& manifold) {
    if (!allows(a, b, manifold)) return false;
    return next ? next(a, b, manifold) : true;
  };
}

}  // namespace impulse2d
