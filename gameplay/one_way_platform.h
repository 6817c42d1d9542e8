#pragma once
/// @file one_way_platform.h
/// One-way platforms: bodies that are solid from above and let others pass from below and
/// from the sides. Built on the world's contact filter, whose decision is kept for as long as
/// a pair touches, so a body rising through a platform is not popped on top halfway through.

#include "core/body.h"
#include "core/manifold.h"
#include "core/world.h"

#include <vector>

namespace impulse2d {

/// The set of one-way platforms of a world and the rule that decides their contacts.
/// Install `filter()` on the world; the object must outlive that filter.
class OneWayPlatforms {
 public:
  /// Makes `platform` one-way, solid for bodies arriving along `up` (a unit vector in the
  /// platform's frame: it turns with the platform). Adding a body twice replaces its `up`.
  /// Throws `Error` for a null handle or a non-unit `up`.
  void add(BodyId platform, vec2 up = vec2(0.0f, 1.0f));
  /// A one-way platform: the body and its local solid direction.
  struct Platform {
    BodyId body;  ///< the platform
    vec2 up;      ///< unit direction, in the platform's frame, it is solid for
  };
  /// Every platform, in the order added (for saving them with the world).
  const std::vector<Platform>& platforms() const { return platforms_; }
  /// True when `body` was added.
  bool contains(BodyId body) const;
  /// The rule, for a pair that starts touching: a pair without a platform is allowed; with a
  /// platform, the contact is kept only when its normal (from the platform to the other body)
  /// is within `max_normal_angle` of the platform's up and the other body is not moving up
  /// through it faster than `rising_speed_tolerance`.
  bool allows(const BodyView& a, const BodyView& b, const Manifold& manifold) const;
  /// A contact filter that applies `allows`, then `next` (when given) to pairs it allows, so a
  /// user's own filter and the platforms coexist. Captures `this`.
  ContactFilter filter(ContactFilter next = nullptr) const;

  /// Radians: widest angle between the contact normal and the platform's up that counts as
  /// arriving from above.
  float max_normal_angle = 0.7853982f;  // 45 degrees
  /// m/s: relative speed along up above which a body counts as rising through the platform.
  float rising_speed_tolerance = 0.05f;

 private:
  const Platform* find(BodyId body) const;
  std::vector<Platform> platforms_;  // in the order added
};

}  // namespace impulse2d
