#pragma once
/// @file scene_frame.h
/// A built-in scene simulated to a golden's step and rendered at the golden size: the frame
/// producer of the golden suite.

#include <functional>

#include "golden/check_run.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/golden_run.h"

namespace impulse2d::demos {
struct Scene;
}

namespace impulse2d {
class World;
}

namespace impulse2d::render {
class FrameRenderer;
}

namespace impulse2d::golden {

/// What a golden frame's PNG says about itself (png_text.h): scene (and file), parameter
/// overrides, step, simulated time, state hash, renderer and program version.
image::PngText frame_metadata(const GoldenSpec& spec, const World& world,
                       const RendererFingerprint& renderer);

/// The renderer of this process at kGoldenWidth x kGoldenHeight, created on first use and
/// shared by every golden check in the process (one OSMesa context per process).
render::FrameRenderer& shared_golden_renderer();

/// Simulates `spec`'s scene (with `variant` applied, when given) from scratch, or from where
/// `start` (when given) leaves the fresh run, to `spec.step` with the scene's camera (fitted
/// to the world the scene starts from either way), then renders it with the HUD and legend as `impulse2d` draws
/// them (dark theme when `spec.dark_theme`), with the body poses (`body_poses`) and the physics samples at
/// `noise_checkpoint_steps(spec.step)` the noise envelope is judged on. Throws `GoldenError`
/// for an unknown scene or a renderer of another size than the golden's, whatever the
/// scene's run or `start` throws, and `demos::UsageError` when `start` leaves the run past
/// `spec.step`.
ProducedFrame produce_scene_frame(const GoldenSpec& spec, render::FrameRenderer& renderer,
                                  const SceneVariant& variant = nullptr,
                                  const RunStart& start = nullptr);

/// Continues `golden_run`, built fresh for `spec`, with `start` (nothing when it is empty).
/// Throws whatever `start` throws, and `demos::UsageError` when the run is then past
/// `spec.step` anyway (a state saved after the golden's step cannot show it).
void start_golden_run(const GoldenSpec& spec, GoldenRun& golden_run, const RunStart& start);

/// A `FrameProducer` of `produce_scene_frame` on the shared renderer.
FrameProducer scene_frame_producer(const GoldenSpec& spec, const SceneVariant& variant = nullptr);

/// A `FrameProducer` of `produce_scene_frame` on `renderer` (of the golden's size), which
/// must outlive it.
FrameProducer scene_frame_producer(const GoldenSpec& spec, render::FrameRenderer& renderer);

}  // namespace impulse2d::golden
