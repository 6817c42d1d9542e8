/// @file scene_frame.cpp
#include "tools/golden_scenes/scene_frame.h"

#include <string>

#include "demos/frame_sequence.h"
#include "demos/scene_camera.h"
#include "demos/scene_registry.h"
#include "demos/scene_run.h"
#include "render/frame_renderer.h"
#include "tools/golden/error.h"

namespace impulse2d::golden {

namespace {

/// "GL_RENDERER | GL_VERSION" split into its two strings.
RendererFingerprint split_fingerprint(const std::string& fingerprint) {
  const std::string separator = " | ";
  const std::size_t at = fingerprint.find(separator);
  if (at == std::string::npos) return RendererFingerprint{fingerprint, ""};
  return RendererFingerprint{fingerprint.substr(0, at), fingerprint.substr(at + separator.size())};
}

/// "body 7" for the first body of slot 7, "body 7 (generation 2)" for a later one, so a body
/// created in a removed body's slot is never compared with its predecessor.
std::string body_name(BodyId id) {
  std::string name = "body " + std::to_string(id.index);
  if (id.generation != 1) name += " (generation " + std::to_string(id.generation) + ")";
  return name;
}

std::vector<BodyPose> body_poses(const World& world) {
  std::vector<BodyPose> poses;
  for (const BodyId id : world.body_ids()) {
    const Body& body = world.body(id);
    poses.push_back(
        BodyPose{body_name(id), body.transform.position.x, body.transform.position.y, body.angle});
  }
  return poses;
}

}  // namespace

render::FrameRenderer& shared_golden_renderer() {
  static render::FrameRenderer renderer(kGoldenWidth, kGoldenHeight);
  return renderer;
}

ProducedFrame produce_scene_frame(const GoldenSpec& spec, render::FrameRenderer& renderer,
                                  const SceneVariant& variant) {
  const demos::Scene* builtin = demos::find_builtin_scene(spec.scene);
  if (builtin == nullptr)
    throw GoldenError("golden '" + spec.id() + "': no built-in scene '" + spec.scene + "'");
  demos::Scene scene = *builtin;
  if (variant) variant(scene);
  demos::Params params(scene.params);
  for (const auto& [name, value] : spec.params) params.set(name, value);

  demos::SceneRun run(scene, params);
  const render::Camera camera =
      demos::scene_camera(scene.view.camera, run.world(), renderer.width(), renderer.height());
  while (run.step_count() < spec.step) run.step();

  render::FrameOptions options;
  options.draw = scene.view.draw;
  if (spec.overlays != 0) options.draw.flags = spec.overlays;
  options.extra_overlays = run.script_overlays();
  render::HudInfo hud;
  hud.scene_name = demos::scene_title(scene);
  hud.frame = spec.step;
  const render::Frame frame =
      renderer.render(run.world(), demos::frame_camera(camera, run), options, hud);

  ProducedFrame produced;
  produced.image = Image{frame.width, frame.height, frame.rgba};
  produced.state_hash = run.world().state_hash();
  produced.bodies = body_poses(run.world());
  produced.renderer = split_fingerprint(renderer.fingerprint());
  return produced;
}

FrameProducer scene_frame_producer(const GoldenSpec& spec, const SceneVariant& variant) {
  return [spec, variant] { return produce_scene_frame(spec, shared_golden_renderer(), variant); };
}

}  // namespace impulse2d::golden
