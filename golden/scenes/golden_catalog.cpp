/// @file golden_catalog.cpp
#include "golden/scenes/golden_catalog.h"

#include "core/debug_draw.h"

namespace impulse2d::golden {

namespace {

/// The overlays that show what the solver did: contacts, impulses, velocities, centres.
constexpr std::uint32_t kPhysicsOverlays =
    draw_shapes | draw_contact_points | draw_contact_normals | draw_normal_impulses |
    draw_friction_impulses | draw_velocities | draw_center_of_mass;

/// The frames chosen for one scene.
struct SceneFrames {
  const char* scene;
  std::int64_t motion;   ///< a step with bodies in flight or colliding
  std::int64_t settled;  ///< a step where the scene has come to rest (or its run ends)
};

/// Chosen by looking at each scene's run: `motion` while bodies fall, slide, swing or
/// collide; `settled` at rest or at the end of the scene's default run.
constexpr SceneFrames kSceneFrames[] = {
    {"tutorial", 240, 900},        {"materials", 75, 480},    {"friction_ramp", 60, 180},
    {"shape_pairs", 30, 240},      {"pyramid", 60, 600},      {"stack", 60, 600},
    {"newtons_cradle", 60, 180},   {"bullet", 20, 90},        {"ball_pit", 120, 600},
    {"random_polygons", 120, 600}, {"platformer", 470, 1110}, {"push", 60, 120},
    {"heavy_on_light", 30, 300},   {"capsules", 60, 480},     {"terrain_chain", 90, 720},
    {"compound", 60, 480},
};

/// The scenes with joints (issue 30): the same frames, their motion overlays with the joints'.
constexpr SceneFrames kJointSceneFrames[] = {
    {"pendulum", 45, 300},  {"double_pendulum", 60, 300}, {"rope_bridge", 90, 480},
    {"car", 120, 480},      {"ragdolls", 120, 600},       {"catapult", 90, 240},
    {"heavy_chain", 60, 300}, {"mouse_drag", 120, 360},
};

/// The scene of events (issue 32): its overlays with the events of the frame's step.
constexpr SceneFrames kEventSceneFrames[] = {
    {"sensors", 57, 324},
};

/// A built-in scene's golden at the default size, parameters and theme.
GoldenSpec builtin(const std::string& scene, const char* name, std::int64_t step,
                   std::uint32_t overlays) {
  GoldenSpec spec;
  spec.scene = scene;
  spec.name = name;
  spec.step = step;
  spec.overlays = overlays;
  return spec;
}

std::vector<GoldenSpec> make_catalog() {
  std::vector<GoldenSpec> catalog;
  for (const SceneFrames& frames : kSceneFrames) {
    const std::string scene = frames.scene;
    catalog.push_back(builtin(scene, "start", 0, 0));
    catalog.push_back(builtin(scene, "motion", frames.motion, 0));
    catalog.push_back(builtin(scene, "settled", frames.settled, 0));
    catalog.push_back(builtin(scene, "motion_overlays", frames.motion, kPhysicsOverlays));
    catalog.push_back(builtin(scene, "settled_overlays", frames.settled, kPhysicsOverlays));
  }
  for (const SceneFrames& frames : kJointSceneFrames) {
    const std::string scene = frames.scene;
    catalog.push_back(builtin(scene, "start", 0, 0));
    catalog.push_back(builtin(scene, "motion", frames.motion, 0));
    catalog.push_back(builtin(scene, "settled", frames.settled, 0));
    catalog.push_back(builtin(scene, "motion_overlays", frames.motion, kPhysicsOverlays | draw_joints));
    catalog.push_back(builtin(scene, "settled_overlays", frames.settled, kPhysicsOverlays | draw_joints));
  }
  for (const SceneFrames& frames : kEventSceneFrames) {
    const std::string scene = frames.scene;
    catalog.push_back(builtin(scene, "start", 0, 0));
    catalog.push_back(builtin(scene, "motion", frames.motion, 0));
    catalog.push_back(builtin(scene, "settled", frames.settled, 0));
    catalog.push_back(builtin(scene, "motion_overlays", frames.motion, kPhysicsOverlays | draw_events));
    catalog.push_back(builtin(scene, "settled_overlays", frames.settled, kPhysicsOverlays | draw_events));
  }
  // Every overlay once, on the scene with every shape pair in contact.
  catalog.push_back(builtin("shape_pairs", "motion_all_overlays", 30, draw_all));
  return catalog;
}

}  // namespace

const std::vector<GoldenSpec>& golden_catalog() {
  static const std::vector<GoldenSpec> catalog = make_catalog();
  return catalog;
}

const GoldenSpec* find_golden(const std::string& id) {
  for (const GoldenSpec& spec : golden_catalog()) {
    if (spec.id() == id) return &spec;
  }
  return nullptr;
}

std::string golden_test_name(const GoldenSpec& spec) { return spec.scene + "_" + spec.name; }

}  // namespace impulse2d::golden
