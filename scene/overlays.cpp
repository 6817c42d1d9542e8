/// @file overlays.cpp
#include "scene/overlays.h"

#include "core/debug_draw.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

const std::vector<OverlayName>& overlay_names() {
  static const std::vector<OverlayName> names = {
      {"none", 0u, "shapes only"},
      {"points", draw_contact_points, "contact points"},
      {"normals", draw_contact_normals, "contact normals"},
      {"impulses", draw_normal_impulses | draw_friction_impulses, "normal and friction impulses"},
      {"normal_impulses", draw_normal_impulses, "normal impulses"},
      {"friction", draw_friction_impulses, "friction impulses"},
      {"penetration", draw_penetration, "penetration depth"},
      {"aabbs", draw_aabbs, "bounding boxes"},
      {"velocities", draw_velocities, "linear velocities"},
      {"com", draw_center_of_mass, "centres of mass"},
      {"sleeping", draw_sleeping, "sleeping bodies dimmed"},
      {"broadphase", draw_broad_phase, "broad-phase pairs"},
      {"ids", draw_body_ids, "body indices"},
      {"joints", draw_joints, "joint anchors, axes, limits, springs, motors and reaction forces"},
      {"events", draw_events,
       "events of the steps since the last frame: touch begin (ring) and end (cross), hits (burst), sensor "
       "begin and end (not in 'all')"},
      {"contacts",
       draw_contact_points | draw_contact_normals | draw_normal_impulses | draw_friction_impulses |
           draw_penetration,
       "points, normals, impulses and penetration"},
      {"all", draw_all, "everything but events"},
  };
  return names;
}

std::uint32_t overlay_flags(const std::string& name) {
  for (const OverlayName& each : overlay_names()) {
    if (name == each.name) return each.flags | draw_shapes;
  }
  std::string known;
  for (const OverlayName& each : overlay_names())
    known += (known.empty() ? "" : ", ") + std::string(each.name);
  throw UsageError("unknown overlay '" + name + "' (known: " + known + ")");
}

std::uint32_t parse_overlays(const std::string& list) {
  std::uint32_t flags = draw_shapes;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, comma - start);
    if (!name.empty()) flags |= overlay_flags(name);
    start = comma + 1;
  }
  return flags;
}

}  // namespace impulse2d::demos
