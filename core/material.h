#pragma once
/// @file material.h
/// Surface and bulk properties of a body, the tutorial's material table, and the rules that
/// combine two bodies' coefficients at a contact.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace impulse2d {

/// What a body is made of.
struct Material {
  std::string name = "Wood";      ///< for display and scene files
  float density = 0.3f;           ///< kg/m^2; 0 makes the body static (infinite mass)
  float restitution = 0.2f;       ///< bounciness, 0 = inelastic, 1 = elastic
  float static_friction = 0.5f;   ///< Coulomb coefficient while sticking (>= dynamic)
  float dynamic_friction = 0.3f;  ///< Coulomb coefficient while sliding
};

/// The tutorial's materials (part 2), each with friction coefficients added.
namespace materials {
Material rock();        ///< density 0.6, restitution 0.1
Material wood();        ///< density 0.3, restitution 0.2
Material metal();       ///< density 1.2, restitution 0.05
Material bouncy_ball(); ///< density 0.3, restitution 0.8
Material super_ball();  ///< density 0.3, restitution 0.95
Material pillow();      ///< density 0.1, restitution 0.2
Material static_ground(); ///< density 0 (static), restitution 0.4; named "Static"
/// All seven, in the tutorial's order.
std::vector<Material> all();
/// The material called `name` (case-sensitive, e.g. "BouncyBall"); throws `Error` if unknown.
Material by_name(const std::string& name);
}  // namespace materials

/// Throws `Error` naming `where` unless density >= 0, 0 <= restitution, frictions >= 0, all
/// finite, and static_friction >= dynamic_friction.
void validate_material(const Material& material, const std::string& where);

/// How two bodies' friction coefficients combine at a contact.
enum class FrictionMixing {
  RootSumSquares,  ///< sqrt(a^2 + b^2), the seed's rule
  GeometricMean,   ///< sqrt(a * b), Box2D's rule
  Product,         ///< a * b, Chipmunk's rule
  Average,         ///< (a + b) / 2
  Minimum,         ///< min(a, b)
  Maximum,         ///< max(a, b)
};

/// How two bodies' restitution coefficients combine at a contact.
enum class RestitutionMixing {
  Minimum,  ///< min(a, b), the tutorial's rule
  Maximum,  ///< max(a, b), Box2D's rule
  Average,  ///< (a + b) / 2
};

// The two mixing rules are defined here so that the narrow phase, which mixes every contact's
// coefficients every step, inlines them.

/// Combines two friction coefficients by `rule`.
inline float mix_friction(float a, float b, FrictionMixing rule) {
  switch (rule) {
    case FrictionMixing::RootSumSquares: return std::sqrt(a * a + b * b);
    case FrictionMixing::GeometricMean: return std::sqrt(a * b);
    case FrictionMixing::Product: return a * b;
    case FrictionMixing::Average: return 0.5f * (a + b);
    case FrictionMixing::Minimum: return std::min(a, b);
    case FrictionMixing::Maximum: return std::max(a, b);
  }
  return 0.0f;
}

/// Combines two restitution coefficients by `rule`.
inline float mix_restitution(float a, float b, RestitutionMixing rule) {
  switch (rule) {
    case RestitutionMixing::Minimum: return std::min(a, b);
    case RestitutionMixing::Maximum: return std::max(a, b);
    case RestitutionMixing::Average: return 0.5f * (a + b);
  }
  return 0.0f;
}

}  // namespace impulse2d
