/// @file timeline_frames.cpp
#include "frames/timeline_frames.h"

#include <algorithm>
#include <cstring>

#include "scene/scene_run.h"
#include "scene/trace_writer.h"
#include "render/frame_scale.h"

namespace impulse2d::demos {

namespace {

render::TimelineSample sample_of(const World& world) {
  render::TimelineSample sample;
  sample.step = world.step_count();
  sample.energy = mechanical_energy(world);
  sample.contacts = static_cast<int>(world.contacts().size());
  for (const Contact& contact : world.contacts()) {
    for (int i = 0; i < contact.point_count; ++i) {
      sample.max_penetration = std::max(sample.max_penetration, contact.points[i].depth);
    }
  }
  return sample;
}

}  // namespace

std::vector<render::TimelineSample> record_timeline(const SceneRun& run, std::int64_t steps) {
  SceneRun ahead(run.scene(), run.params());
  const std::int64_t every = std::max<std::int64_t>(1, steps / 2048);
  std::vector<render::TimelineSample> samples{sample_of(ahead.world())};
  while (ahead.step_count() < steps) {
    ahead.step();
    if (ahead.step_count() % every == 0 || ahead.step_count() == steps) samples.push_back(sample_of(ahead.world()));
  }
  return samples;
}

TimelineFrames::TimelineFrames(const SceneRun& run, std::int64_t steps, int width, int height, render::Theme theme)
    : samples_(record_timeline(run, steps)),
      theme_(theme),
      scale_(render::frame_scale(width, height)),
      strip_(width, render::timeline_height(width, height)) {}

void TimelineFrames::append(render::Frame& frame, std::int64_t step) {
  const int width = strip_.width();
  const int height = strip_.height();
  const render::Camera camera = render::Camera::centered(
      vec2(0.5f * static_cast<float>(width), 0.5f * static_cast<float>(height)), 1.0f, width, height);
  const render::ThemePalette palette = render::theme_palette(theme_);
  strip_.render_primitives(camera, palette.background, [&](render::PrimitiveRenderer& draw) {
    render::draw_timeline(draw, samples_, step, palette, scale_);
  }, strip_frame_);
  const std::size_t scene_bytes = frame.rgba.size();
  frame.rgba.resize(scene_bytes + strip_frame_.rgba.size());
  std::memcpy(frame.rgba.data() + scene_bytes, strip_frame_.rgba.data(), strip_frame_.rgba.size());
  frame.height += height;
}

}  // namespace impulse2d::demos
