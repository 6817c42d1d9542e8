/// @file island_overlay.cpp
#include "render/island_overlay.h"

#include "core/world.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <numeric>

namespace impulse2d::render {

namespace {

bool is_dynamic(const World& world, std::uint32_t slot) {
  return world.slot_alive(slot) && world.body_slots()[slot].type == BodyType::Dynamic;
}

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t slot) {
  while (parent[slot] != slot) {
    parent[slot] = parent[parent[slot]];
    slot = parent[slot];
  }
  return slot;
}

}  // namespace

std::vector<int> island_of_slots(const World& world) {
  const auto slots = static_cast<std::uint32_t>(world.body_slots().size());
  std::vector<std::uint32_t> parent(slots);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Contact& contact : world.contacts()) {
    const std::uint32_t a = contact.body_a.index;
    const std::uint32_t b = contact.body_b.index;
    if (!contact.enabled || !is_dynamic(world, a) || !is_dynamic(world, b)) continue;
    const std::uint32_t root_a = root(parent, a);
    const std::uint32_t root_b = root(parent, b);
    parent[std::max(root_a, root_b)] = std::min(root_a, root_b);  // the lowest slot is the root
  }
  std::vector<int> island(slots, -1);
  int next = 0;
  for (std::uint32_t slot = 0; slot < slots; ++slot) {
    if (!is_dynamic(world, slot)) continue;
    const std::uint32_t top = root(parent, slot);
    if (island[top] < 0) island[top] = next++;  // roots come first: top <= slot
    island[slot] = island[top];
  }
  return island;
}

Color island_color(int island) {
  // Okabe-Ito without black and grey, then two more that stay apart from them.
  static const Color colors[8] = {{0.90f, 0.62f, 0.00f, 1.0f}, {0.34f, 0.71f, 0.91f, 1.0f},
                                  {0.00f, 0.62f, 0.45f, 1.0f}, {0.94f, 0.89f, 0.26f, 1.0f},
                                  {0.00f, 0.45f, 0.70f, 1.0f}, {0.84f, 0.37f, 0.00f, 1.0f},
                                  {0.80f, 0.47f, 0.65f, 1.0f}, {0.45f, 0.25f, 0.60f, 1.0f}};
  return colors[static_cast<unsigned>(island) % 8u];
}

void draw_islands(PrimitiveRenderer& renderer, const World& world, int scale) {
  const std::vector<int> island = island_of_slots(world);
  const std::vector<Body>& bodies = world.body_slots();
  for (const Contact& contact : world.contacts()) {
    if (!contact.enabled || contact.point_count == 0) continue;
    const std::uint32_t a = contact.body_a.index;
    const std::uint32_t b = contact.body_b.index;
    const int which = island[a] >= 0 ? island[a] : island[b];
    if (which < 0) continue;
    const vec2 from = island[a] >= 0 ? bodies[a].transform.position : contact.points[0].point;
    const vec2 to = island[b] >= 0 ? bodies[b].transform.position : contact.points[0].point;
    renderer.draw_segment(from, to, island_color(which));
  }
  const float dot = 5.0f * static_cast<float>(std::max(scale, 1));
  for (std::uint32_t slot = 0; slot < bodies.size(); ++slot) {
    if (island[slot] >= 0) renderer.draw_point(bodies[slot].transform.position, dot, island_color(island[slot]));
  }
}

}  // namespace impulse2d::render
