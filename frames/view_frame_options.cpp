/// @file view_frame_options.cpp
#include "frames/view_frame_options.h"

#include <cstdio>

#include "scene/scene_run.h"

namespace impulse2d::demos {

render::FrameOptions view_frame_options(const SceneRun& run, const DebugDrawOptions& draw, render::Theme theme) {
  const SceneView& view = run.scene().view;
  render::FrameOptions options;
  options.draw = draw;
  options.theme = theme;
  options.show_hud = view.show_hud;
  options.show_legend = view.show_legend;
  options.text_scale = view.text_scale;
  options.contacts.max_arrow_pixels = view.max_arrow_pixels;
  options.contacts.feature_ids = view.show_feature_ids;
  options.islands = view.show_islands;
  options.body_labels = run.body_labels();
  options.extra_overlays = run.script_overlays();
  return options;
}

void update_view_frame(const SceneRun& run, render::FrameOptions& options, render::HudInfo& hud) {
  const int highlight = run.scene().view.highlight_body;
  options.highlight = highlight >= 0 ? run.slot_of(highlight) : std::nullopt;
  hud.extra_lines = view_hud_lines(run);
}

std::vector<std::string> view_hud_lines(const SceneRun& run) {
  const SceneView& view = run.scene().view;
  std::vector<std::string> lines;
  char text[160];
  if (view.show_settings) {
    const WorldSettings& settings = run.world().settings();
    std::snprintf(text, sizeof(text), "%s  dt %.4g s x%d  iterations %d/%d  warm %s  sleep %s",
                  solver_name(settings.solver), static_cast<double>(settings.time_step), settings.substeps,
                  settings.velocity_iterations, settings.position_iterations,
                  settings.warm_starting ? "on" : "off", settings.enable_sleeping ? "on" : "off");
    lines.push_back(text);
  }
  if (view.show_timings) {
    const StepStats& stats = run.world().stats();
    std::snprintf(text, sizeof(text), "ms: broad %.2f narrow %.2f solve %.2f integ %.2f pos %.2f = %.2f",
                  stats.broad_phase_ms, stats.narrow_phase_ms, stats.solver_ms, stats.integrate_ms,
                  stats.position_ms, stats.total_ms);
    lines.push_back(text);
  }
  return lines;
}

}  // namespace impulse2d::demos
