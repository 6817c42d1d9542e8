// libFuzzer target: `World::restore_snapshot` on arbitrary bytes (seeds in
// tests/fuzz/corpus/restore_snapshot: version-2 snapshots of small worlds saved with
// `World::save_snapshot`: a ball dropped on a box, boxes falling through a polygon sensor, a
// capsule and a rounded box on a segment floor). A buffer is either refused with `Error`, leaving the world
// exactly as it was, or accepted; an accepted world must save to bytes that restore again to
// the same bytes, and step a few times without crashing.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/error.h"
#include "core/shape.h"
#include "core/world.h"

namespace {

using namespace impulse2d;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_restore_snapshot: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // A world with a state of its own, so that a refusal can be seen to keep it.
  World world;
  BodyDef ball;
  ball.position = {0.0f, 2.0f};
  world.create_body(ball, make_circle(0.5f));
  BodyDef ground;
  ground.type = BodyType::Static;
  world.create_body(ground, make_box({5.0f, 0.5f}));
  world.step();
  const std::vector<std::uint8_t> before = world.save_snapshot();

  try {
    world.restore_snapshot(data, size);
  } catch (const Error&) {
    if (world.save_snapshot() != before) fail("a refused snapshot changed the world");
    return 0;
  }
  const std::vector<std::uint8_t> saved = world.save_snapshot();
  World again;
  try {
    again.restore_snapshot(saved);
  } catch (const Error&) {
    fail("a world restored from accepted bytes saves bytes it refuses");
  }
  if (again.save_snapshot() != saved) fail("save, restore, save differs");
  // Stepping an accepted world must not crash (settings and bodies passed the core's checks).
  for (int i = 0; i < 3; ++i) world.step();
  return 0;
}
