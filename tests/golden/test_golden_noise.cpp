/// @file test_golden_noise.cpp
/// The noise envelope tells a rounding change from a physics change. Two mutations of the
/// same number, each body's polygon inertia, run against committed goldens:
/// - the inertia summed over the polygon's triangles in the opposite order (the same
///   formula, only the rounding differs) must be *numerical noise*;
/// - the inertia 5% too large must be *behaviour changed*, naming what left the envelope.
/// Both use the chaotic random_polygons scene, where the reordered sum alone moves bodies
/// by centimetres by the golden frame. Variants never write goldens or artifacts.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>

#include "core/shape.h"
#include "core/solver/world_state.h"
#include "core/world.h"
#include "scene/scene.h"
#include "tests/golden/test_golden_support.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

/// The order in which the polygon's triangle fan is summed.
enum class SumOrder { AsTheCore, Reversed };

/// Inertia about the centroid of a polygon of `density`: the core's formula
/// (core/shape.cpp, compute_polygon_mass), its fan of triangles summed in `order`.
float polygon_inertia(const Polygon& polygon, float density, SumOrder order) {
  const int count = polygon.count;
  const vec2 origin = polygon.vertices[0];
  float area = 0.0f;
  vec2 centroid_moment{0.0f, 0.0f};
  float second_moment = 0.0f;
  for (int k = 0; k < count; ++k) {
    const int i = order == SumOrder::AsTheCore ? k : count - 1 - k;
    const vec2 p1 = polygon.vertices[i] - origin;
    const vec2 p2 = polygon.vertices[(i + 1) % count] - origin;
    const float twice_triangle_area = cross(p1, p2);
    area += 0.5f * twice_triangle_area;
    centroid_moment += (twice_triangle_area / 6.0f) * (p1 + p2);
    second_moment += (twice_triangle_area / 12.0f) * (p1.x * p1.x + p1.x * p2.x + p2.x * p2.x +
                                                      p1.y * p1.y + p1.y * p2.y + p2.y * p2.y);
  }
  const vec2 centroid_offset = centroid_moment / area;
  return density * (second_moment - area * length_squared(centroid_offset));
}

/// What a mutation did to the bodies' inertias.
struct MutationCount {
  int bodies = 0;   ///< rotating dynamic polygons
  int changed = 0;  ///< of those, how many got a different float inertia
};

/// Replaces the inertia of every rotating dynamic polygon, right after the scene's build, by
/// `polygon_inertia(order) * factor`. Inertia is derived data the world computes once at
/// creation; the test writes it in place (the body object itself is not const), which is
/// exactly what a changed inertia formula in the core would leave there.
SceneVariant mutate_polygon_inertia(SumOrder order, float factor, MutationCount* count) {
  return [order, factor, count](demos::Scene& scene) {
    scene.build = [build = scene.build, order, factor, count](World& world,
                                                               const demos::Params& params) {
      build(world, params);
      *count = {};
      for (const BodyId id : world.body_ids()) {
        Body& body = WorldState::of(world).bodies[id.index];
        if (body.type != BodyType::Dynamic || body.shape.type() != ShapeType::Polygon ||
            body.inverse_inertia == 0.0f) {
          continue;
        }
        const float density = body.material.density;
        if (polygon_inertia(body.shape.polygon(), density, SumOrder::AsTheCore) != body.inertia) {
          throw std::logic_error("polygon_inertia no longer mirrors the core's formula");
        }
        const float inertia = polygon_inertia(body.shape.polygon(), density, order) * factor;
        ++count->bodies;
        if (inertia != body.inertia) ++count->changed;
        body.inertia = inertia;
        body.inverse_inertia = 1.0f / inertia;
      }
    };
  };
}


constexpr const char* kGoldens[] = {"random_polygons/motion", "random_polygons/settled"};

TEST(GoldenNoise, ReorderedInertiaSumIsNumericalNoise) {
  for (const char* golden : kGoldens) {
    MutationCount count;
    const CheckOutcome outcome =
        testing::check_golden_variant(golden, mutate_polygon_inertia(SumOrder::Reversed, 1.0f, &count));
    std::cout << outcome.message() << "\n";
    ASSERT_GT(count.bodies, 0) << golden;
    // The reorder must really change some inertias (else this would test nothing) ...
    EXPECT_GT(count.changed, 0) << golden;
    // ... and that must really change the run, or the class would be "passed". It stays
    // inside the envelope; random_polygons amplifies it to metres (2 m at motion), beyond 1 %
    // of the scene's size, so since issue 29 the honest verdict is "cannot tell", and never
    // "behaviour changed".
    EXPECT_TRUE(outcome.failure_class == FailureClass::NumericalNoise ||
                outcome.failure_class == FailureClass::CannotTell)
        << outcome.message();
    ASSERT_TRUE(outcome.check.noise.has_value()) << golden;
    EXPECT_TRUE(outcome.check.noise->within()) << golden;
  }
}

TEST(GoldenNoise, FivePercentInertiaErrorIsBehaviourChanged) {
  for (const char* golden : kGoldens) {
    MutationCount count;
    const CheckOutcome outcome =
        testing::check_golden_variant(golden, mutate_polygon_inertia(SumOrder::AsTheCore, 1.05f, &count));
    std::cout << outcome.message() << "\n";
    ASSERT_GT(count.bodies, 0) << golden;
    EXPECT_EQ(count.changed, count.bodies) << golden;
    EXPECT_EQ(outcome.failure_class, FailureClass::BehaviourChanged) << outcome.message();
    ASSERT_TRUE(outcome.check.noise.has_value()) << golden;
    EXPECT_FALSE(outcome.check.noise->escapes.empty()) << golden;
    EXPECT_NE(outcome.message().find("noise envelope"), std::string::npos) << outcome.message();
  }
}

TEST(GoldenNoise, UnmutatedRunsPass) {
  for (const char* golden : kGoldens) {
    MutationCount count;
    const CheckOutcome outcome =
        testing::check_golden_variant(golden, mutate_polygon_inertia(SumOrder::AsTheCore, 1.0f, &count));
    EXPECT_GT(count.bodies, 0) << golden;
    EXPECT_EQ(count.changed, 0) << golden;
    EXPECT_TRUE(testing::passes_on_this_renderer(outcome)) << outcome.message();
  }
}

}  // namespace
}  // namespace impulse2d::golden
