/// @file command_trace.cpp
/// `impulse2d trace`: per-step body states of a run as CSV or JSON.
#include <CLI/CLI.hpp>
#include <memory>

#include "app/command.h"
#include "app/scene_command.h"
#include "scene/run_limits.h"
#include "scene/trace_writer.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d trace`.
struct TraceArguments {
  SceneArguments scene;        ///< what to run (the scene's length unless steps is given)
  std::int64_t every = 1;      ///< sample every k-th step
  std::string format = "csv";  ///< csv or json
};

/// Writes the trace of a run to `out`.
void trace_scene(const TraceArguments& arguments, std::ostream& out) {
  const ResolvedScene resolved = resolve(arguments.scene);
  TraceFormat format = TraceFormat::Csv;
  if (arguments.format == "json") {
    format = TraceFormat::Json;
  } else if (arguments.format != "csv") {
    throw UsageError("--format '" + arguments.format + "': expected csv or json");
  }
  const std::unique_ptr<SceneRun> run = start_run(resolved, arguments.scene);
  if (arguments.every < 1) throw UsageError("--every must be >= 1");
  std::int64_t moving = 0;
  for (const BodyId id : run->world().body_ids()) {
    moving += run->world().body(id).type == BodyType::Static ? 0 : 1;
  }
  const std::int64_t samples = resolved.steps / arguments.every + 2;
  if (moving > 0 && samples > limits::max_trace_rows / moving) {
    throw UsageError("trace: --steps " + std::to_string(resolved.steps) + " --every " +
                     std::to_string(arguments.every) + " would print about " +
                     std::to_string(samples) + " samples of " + std::to_string(moving) +
                     " bodies; the limit is " + std::to_string(limits::max_trace_rows) +
                     " rows (raise --every or lower --steps)");
  }
  const std::string text = trace_run(*run, resolved.steps, arguments.every, format);
  warn_divergences(*run);
  out << text;
}

}  // namespace

Command add_trace_command(CLI::App& program, const ProgramOptions&) {
  auto trace = std::make_shared<TraceArguments>();
  CLI::App* command = program.add_subcommand(
      "trace", "print per-step body states (step,t,body,x,y,angle,vx,vy,omega,contacts,energy)");
  add_scene_options(*command, trace->scene, true);
  command->add_option("--steps,-n", trace->scene.steps, "steps to simulate (default: the scene's)");
  command->add_option("--every,-k", trace->every, "sample every k-th step")->capture_default_str();
  command->add_option("--format", trace->format, "csv or json")->capture_default_str();

  Command result;
  result.parser = command;
  result.dry_run = [trace](std::ostream&) { check_scene_arguments(trace->scene, std::nullopt); };
  result.run = [trace](std::ostream& out) {
    trace_scene(*trace, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos
