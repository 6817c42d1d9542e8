/// @file scene_frame.cpp
#include "golden/scenes/scene_frame.h"

#include <string>

#include "frames/frame_metadata.h"
#include "frames/frame_sequence.h"
#include "frames/scene_camera.h"
#include "demos/scene_registry.h"
#include "scene/scene_run.h"
#include "frames/view_frame_options.h"
#include "golden/scenes/golden_run.h"
#include "render/frame_renderer.h"
#include "golden/error.h"
#include "scene/usage_error.h"

namespace impulse2d::golden {

image::PngText frame_metadata(const GoldenSpec& spec, const World& world,
                       const RendererFingerprint& renderer) {
  std::string parameters;
  for (const auto& [name, value] : spec.params) {
    parameters += (parameters.empty() ? "" : " ") + name + "=" + value;
  }
  const std::string scene =
      spec.scene_file.empty() ? spec.scene : spec.scene + " (" + spec.scene_file + ")";
  return demos::frame_metadata(scene, parameters, world, renderer.describe());
}

render::FrameRenderer& shared_golden_renderer() {
  static render::FrameRenderer renderer(kGoldenWidth, kGoldenHeight);
  return renderer;
}

void start_golden_run(const GoldenSpec& spec, GoldenRun& golden_run, const RunStart& start) {
  if (!start) return;
  start(golden_run.run(), spec.step);
  const std::int64_t step = golden_run.run().step_count();
  if (step > spec.step) {
    throw demos::UsageError("golden '" + spec.id() + "' is the world after " +
                            std::to_string(spec.step) + " steps; the loaded state is after " +
                            std::to_string(step) + " (save it at step " +
                            std::to_string(spec.step) + " or earlier)");
  }
}

ProducedFrame produce_scene_frame(const GoldenSpec& spec, render::FrameRenderer& renderer,
                                  const SceneVariant& variant, const RunStart& start) {
  if (renderer.width() != spec.width || renderer.height() != spec.height) {
    throw GoldenError("golden '" + spec.id() + "' is " + std::to_string(spec.width) + "x" +
                      std::to_string(spec.height) + ", the renderer draws " +
                      std::to_string(renderer.width()) + "x" + std::to_string(renderer.height()));
  }
  GoldenRun golden_run(spec, variant);
  start_golden_run(spec, golden_run, start);
  const demos::Scene& scene = golden_run.scene();
  demos::SceneRun& run = golden_run.run();
  // Fitted to the world the scene starts from, also when `start` restored a saved state.
  const render::Camera camera = demos::run_camera(run, renderer.width(), renderer.height());
  ProducedFrame produced;
  for (const std::int64_t checkpoint : noise_checkpoint_steps(spec.step)) {
    while (run.step_count() < checkpoint) golden_run.step();
    produced.samples.push_back(sample_physics(run.world()));
  }

  DebugDrawOptions draw = scene.view.draw;
  if (spec.overlays != 0) draw.flags = spec.overlays;
  render::FrameOptions options = demos::view_frame_options(
      run, draw, spec.dark_theme ? render::Theme::Dark : render::Theme::Light);
  render::HudInfo hud;
  hud.scene_name = demos::scene_title(scene);
  hud.step = spec.step;
  demos::update_view_frame(run, options, hud);
  const render::Frame frame =
      renderer.render(run.world(), demos::frame_camera(camera, run), options, hud);

  produced.image = image::Image{frame.width, frame.height, frame.rgba, {}};
  produced.state_hash = run.world().state_hash();
  produced.bodies = golden_run.body_poses();
  produced.slot_bodies = body_poses(run.world());
  produced.renderer = split_fingerprint(renderer.fingerprint());
  produced.image.text = frame_metadata(spec, run.world(), produced.renderer);
  return produced;
}

FrameProducer scene_frame_producer(const GoldenSpec& spec, const SceneVariant& variant) {
  return [spec, variant] { return produce_scene_frame(spec, shared_golden_renderer(), variant); };
}

FrameProducer scene_frame_producer(const GoldenSpec& spec, render::FrameRenderer& renderer) {
  return [spec, &renderer] { return produce_scene_frame(spec, renderer); };
}

}  // namespace impulse2d::golden
