/// @file world_chain.cpp
/// World::create_chain: a chain's links as static bodies.

#include "core/error.h"
#include "core/world.h"

#include <cmath>

namespace impulse2d {

std::vector<BodyId> World::create_chain(const BodyDef& def, const vec2* points, int count,
                                        bool loop) {
  if (def.type != BodyType::Static) {
    throw Error("World::create_chain: a chain is level geometry: its body must be static");
  }
  if (!(is_finite(def.position) && std::isfinite(def.angle))) {
    throw Error("World::create_chain: position and angle must be finite");
  }
  if (points == nullptr) throw Error("World::create_chain: points is null");
  const std::vector<ChainLink> links = make_chain(points, count, loop);
  const Transform place{def.position, Rotation::from_angle(def.angle)};
  // make_chain checked the points; the first link's create_body checks `def`, which every
  // link shares, so a failure comes before any body is made.
  BodyDef link_def = def;
  std::vector<BodyId> bodies;
  bodies.reserve(links.size());
  for (const ChainLink& link : links) {
    link_def.position = place.apply(link.position);
    bodies.push_back(create_body(link_def, link.shape));
  }
  return bodies;
}

}  // namespace impulse2d
