/// @file scene_command.cpp
#include "app/scene_command.h"
#include "app/strict_number_check.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <iostream>

#include "demos/scene_registry.h"
#include "scene/overlays.h"
#include "scene/run_limits.h"
#include "scene/strict_number.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

void add_scene_options(CLI::App& command, SceneArguments& arguments, bool scene_required) {
  CLI::Option* scene = command.add_option(
      "scene", arguments.scene, "built-in scene name (see `impulse2d list`) or a .json scene file");
  if (scene_required) scene->required();
  command.add_option("--param,-p", arguments.params,
                     "scene parameter key=value, one per flag (repeat it: -p rows=8 -p seed=3)")
      ->allow_extra_args(false);
  command.add_flag("--strict", arguments.strict,
                   "a body that diverges (non-finite state) is an error (exit 1), not a warning");
  command.add_option("--workers", arguments.workers,
                     "threads sharing each physics step, 1..64 (the states are bit-identical "
                     "for any count)")
      ->capture_default_str()
      ->check(whole_number_check());
}

void add_backend_option(CLI::App& command, std::string& backend) {
  command.add_option("--backend", backend,
                     "offscreen renderer: osmesa or egl (default: $IMPULSE2D_BACKEND, else osmesa)")
      ->check(CLI::IsMember({"osmesa", "egl"}));
}

std::string overlay_help() {
  std::string text = "comma-separated overlays (default: the scene's):";
  for (const OverlayName& each : overlay_names()) {
    text += std::string("\n  ") + each.name + ": " + each.description;
  }
  return text;
}

ResolvedScene resolve(const SceneArguments& arguments, bool check_events) {
  ResolvedScene resolved{resolve_scene(arguments.scene), Params{}, 0};
  resolved.params = Params(resolved.scene.params);
  for (const std::string& assignment : arguments.params) resolved.params.set_assignment(assignment);
  resolved.steps = arguments.steps ? *arguments.steps : resolved.scene.view.steps;
  if (resolved.steps < 0 || resolved.steps > limits::max_steps) {
    throw UsageError("--steps " + std::to_string(resolved.steps) + ": must be 0.." +
                     std::to_string(limits::max_steps));
  }
  if (arguments.workers < 1 || arguments.workers > 64) {
    throw UsageError("--workers " + std::to_string(arguments.workers) + ": must be 1..64");
  }
  resolved.scene.settings.worker_count = arguments.workers;
  if (check_events) check_events_in_run(resolved, resolved.steps);
  return resolved;
}

void check_events_in_run(const ResolvedScene& resolved, std::int64_t last_step) {
  for (const SceneEvent& event : resolved.scene.events) {
    if (event.step > last_step) {
      throw UsageError(resolved.scene.source + ": " + event.origin + ".step: step " +
                       std::to_string(event.step) + " is after the end of the run (steps 0.." +
                       std::to_string(last_step) +
                       "; change it with --steps or the file's run.steps)");
    }
  }
}

std::unique_ptr<SceneRun> start_run(const ResolvedScene& resolved, const SceneArguments& arguments) {
  auto run = std::make_unique<SceneRun>(resolved.scene, resolved.params);
  run->set_strict(arguments.strict);
  return run;
}

void check_trails(const TrailSelection& trails, const SceneRun& run, const std::string& option) {
  for (const std::uint32_t slot : trails.slots) {
    if (slot >= static_cast<std::uint32_t>(run.bodies_in_run())) {
      throw UsageError(option + ": body " + std::to_string(slot) + " does not exist (scene " +
                       run.scene().name + " has " + std::to_string(run.bodies_in_run()) +
                       " bodies, 0.." + std::to_string(run.bodies_in_run() - 1) + ")");
    }
  }
}

void warn_divergences(const SceneRun& run) {
  const std::vector<Divergence>& divergences = run.divergences();
  for (std::size_t i = 0; i < divergences.size() && i < 10; ++i) {
    std::cerr << "impulse2d: warning: " << describe_divergence(run.scene(), divergences[i])
              << "\n";
  }
  if (divergences.size() > 10) {
    std::cerr << "impulse2d: warning: ... and " << divergences.size() - 10
              << " more divergences (--strict stops at the first)\n";
  }
}

render::Theme theme_of(const std::string& name) {
  const std::optional<render::Theme> theme = render::parse_theme(name);
  if (!theme) throw UsageError("--theme '" + name + "': expected light or dark");
  return *theme;
}

std::pair<int, int> parse_size(const std::string& text, const std::string& option) {
  const std::size_t x = text.find('x');
  const auto side = [&](const std::string& part) {
    const std::optional<std::int64_t> value = parse_whole_number(part, 8192);
    if (!value || *value < 16) {
      throw UsageError(option + " '" + text +
                       "': expected WxH with each side 16..8192 pixels, e.g. 800x600 (" +
                       whole_number_syntax + ")");
    }
    return static_cast<int>(*value);
  };
  if (x == std::string::npos) side("");
  return {side(text.substr(0, x)), side(text.substr(x + 1))};
}

std::uint32_t parse_overlays_option(const std::string& list) {
  try {
    return parse_overlays(list);
  } catch (const UsageError& error) {
    throw UsageError("--overlays '" + list + "': " + error.what());
  }
}

}  // namespace impulse2d::demos
