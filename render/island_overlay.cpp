/// @file island_overlay.cpp
#include "render/island_overlay.h"

#include "core/world.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <numeric>

namespace impulse2d::render {

namespace {

// 1 for each slot that holds a living dynamic body, up to the last living body's slot.
std::vector<std::uint8_t> dynamic_slots(const World& world) {
  std::vector<std::uint8_t> dynamic;
  for (const BodyId id : world.body_ids()) {
    if (dynamic.size() <= id.index) dynamic.resize(id.index + 1, 0);
    dynamic[id.index] = world.body(id).type == BodyType::Dynamic ? 1 : 0;
  }
  return dynamic;
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
  const std::vector<std::uint8_t> dynamic = dynamic_slots(world);
  const auto slots = static_cast<std::uint32_t>(dynamic.size());
  std::vector<std::uint32_t> parent(slots);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Contact& contact : world.contacts()) {
    const std::uint32_t a = contact.body_a.index;
    const std::uint32_t b = contact.body_b.index;
    if (!contact.enabled || !dynamic[a] || !dynamic[b]) continue;
    const std::uint32_t root_a = root(parent, a);
    const std::uint32_t root_b = root(parent, b);
    parent[std::max(root_a, root_b)] = std::min(root_a, root_b);  // the lowest slot is the root
  }
  std::vector<int> island(slots, -1);
  int next = 0;
  for (std::uint32_t slot = 0; slot < slots; ++slot) {
    if (!dynamic[slot]) continue;
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

void draw_islands(PrimitiveRenderer& renderer, const World& world) {
  const std::vector<int> island = island_of_slots(world);
  for (const Contact& contact : world.contacts()) {
    if (!contact.enabled || contact.point_count == 0) continue;
    const std::uint32_t a = contact.body_a.index;
    const std::uint32_t b = contact.body_b.index;
    const int which = island[a] >= 0 ? island[a] : island[b];
    if (which < 0) continue;
    const vec2 from =
        island[a] >= 0 ? world.body(contact.body_a).transform.position : contact.points[0].point;
    const vec2 to =
        island[b] >= 0 ? world.body(contact.body_b).transform.position : contact.points[0].point;
    renderer.draw_segment(from, to, island_color(which));
  }
  for (const BodyId id : world.body_ids()) {
    const int which = island[id.index];
    if (which >= 0) renderer.draw_point(world.body(id).transform.position, 5.0f, island_color(which));
  }
}

}  // namespace impulse2d::render
