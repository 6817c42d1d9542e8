// Shape queries allocate nothing for a caller who passes a buffer (issue 32). Own binary: it
// counts allocations (tests/support/allocation_counter.cpp replaces the global operator new).
#include "core/world.h"

#include <gtest/gtest.h>

#include "tests/support/allocation_counter.h"

using impulse2d::testing::allocation_count;

using namespace impulse2d;

TEST(QueryAllocations, OverlapCastAndRayAllocateNothing) {
  World world;
  BodyDef def;
  for (int i = 0; i < 200; ++i) {
    def.position = {static_cast<float>(i % 20), static_cast<float>(i / 20)};
    world.create_body(def, i % 2 ? make_circle(0.3f) : make_oriented_box({0.3f, 0.2f}));
  }
  for (int i = 0; i < 5; ++i) world.step();
  BodyId buffer[16];
  const Shape box = make_box({2.0f, 2.0f});
  const Shape circle = make_circle(0.2f);
  QueryFilter filter;
  filter.accept = [&buffer](BodyId id) { return id != buffer[0] || true; };
  const long before = allocation_count();
  int found = 0;
  for (int i = 0; i < 50; ++i) {
    found += world.overlap_shape(box, Transform{{5.0f, 5.0f}, Rotation{}}, buffer, 16, filter);
    found += world.cast_shape(circle, Transform{{-5.0f, 4.2f}, Rotation{}}, {40.0f, 0.0f}, filter).has_value();
    found += world.raycast_closest({-5.0f, 3.0f}, {40.0f, 0.0f}, filter).has_value();
  }
  EXPECT_EQ(allocation_count() - before, 0);
  EXPECT_GT(found, 0);
}
