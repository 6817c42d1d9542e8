#include "core/material.h"

#include "core/error.h"

#include <cmath>

namespace impulse2d {
namespace materials {

// Density and restitution are the tutorial's (part 2). The tutorial gives no friction; the
// coefficients below are typical handbook values for the named surface on a hard floor,
// with static >= dynamic as the seed requires.
Material rock() { return {"Rock", 0.6f, 0.1f, 0.7f, 0.5f}; }
Material wood() { return {"Wood", 0.3f, 0.2f, 0.5f, 0.3f}; }
Material metal() { return {"Metal", 1.2f, 0.05f, 0.74f, 0.57f}; }
Material bouncy_ball() { return {"BouncyBall", 0.3f, 0.8f, 0.9f, 0.8f}; }
Material super_ball() { return {"SuperBall", 0.3f, 0.95f, 0.9f, 0.8f}; }
Material pillow() { return {"Pillow", 0.1f, 0.2f, 0.6f, 0.5f}; }
Material static_ground() { return {"Static", 0.0f, 0.4f, 0.6f, 0.4f}; }

std::vector<Material> all() {
  return {rock(), wood(), metal(), bouncy_ball(), super_ball(), pillow(), static_ground()};
}

Material by_name(const std::string& name) {
  for (const Material& material : all()) {
    if (material.name == name) return material;
  }
  std::string known;
  for (const Material& material : all()) known += (known.empty() ? "" : ", ") + material.name;
  throw Error("unknown material '" + name + "' (known: " + known + ")");
}

}  // namespace materials

void validate_material(const Material& material, const std::string& where) {
  auto require = [&](bool ok, const char* field, const char* reason) {
    if (!ok) throw Error(where + "." + field + ": " + reason);
  };
  require(std::isfinite(material.density) && material.density >= 0.0f, "density",
          "must be finite and >= 0");
  require(std::isfinite(material.restitution) && material.restitution >= 0.0f, "restitution",
          "must be finite and >= 0");
  require(std::isfinite(material.static_friction) && material.static_friction >= 0.0f,
          "static_friction", "must be finite and >= 0");
  require(std::isfinite(material.dynamic_friction) && material.dynamic_friction >= 0.0f,
          "dynamic_friction", "must be finite and >= 0");
  require(material.static_friction >= material.dynamic_friction, "static_friction",
          "must be >= dynamic_friction");
}

}  // namespace impulse2d
