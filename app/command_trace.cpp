/// @file command_trace.cpp
/// `impulse2d trace`: per-step body states of a run as CSV or JSON.
#include <CLI/CLI.hpp>
#include <memory>

#include "app/command.h"
#include "app/scene_command.h"
#include "app/strict_number_check.h"
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

/// A trace, checked and ready: what `trace_scene` runs and `print_trace_plan` shows.
struct TraceJob {
  ResolvedScene resolved;                 ///< the scene, its parameters and length
  TraceFormat format = TraceFormat::Csv;  ///< csv or json
  std::int64_t samples = 0;               ///< steps printed: 0, k, 2k, ... and the last
  std::int64_t moving = 0;                ///< bodies that are not static, one row each
  std::unique_ptr<SceneRun> run;          ///< the run, built and not yet stepped
};

/// Every check a trace makes before any work; the run and --dry-run both start here. Throws
/// `UsageError`.
TraceJob prepare_trace(const TraceArguments& arguments) {
  TraceJob job;
  job.resolved = resolve(arguments.scene);
  if (arguments.format == "json") {
    job.format = TraceFormat::Json;
  } else if (arguments.format != "csv") {
    throw UsageError("--format '" + arguments.format + "': expected csv or json");
  }
  if (arguments.every < 1) {
    throw UsageError("--every " + std::to_string(arguments.every) + ": must be at least 1");
  }
  job.run = start_run(job.resolved, arguments.scene);
  for (const BodyId id : job.run->world().body_ids()) {
    job.moving += job.run->world().body(id).type == BodyType::Static ? 0 : 1;
  }
  const std::int64_t steps = job.resolved.steps;
  job.samples = steps / arguments.every + 2;
  if (job.moving > 0 && job.samples > limits::max_trace_rows / job.moving) {
    throw UsageError("trace: --steps " + std::to_string(steps) + " --every " +
                     std::to_string(arguments.every) + " would print about " +
                     std::to_string(job.samples) + " samples of " + std::to_string(job.moving) +
                     " bodies; the limit is " + std::to_string(limits::max_trace_rows) +
                     " rows (raise --every or lower --steps)");
  }
  // Exactly: steps 0, k, 2k, ... and the last step when k does not divide it.
  job.samples = steps / arguments.every + 1 + (steps % arguments.every != 0 ? 1 : 0);
  return job;
}

/// What `trace` would print, for --dry-run.
void print_trace_plan(const TraceJob& job, const TraceArguments& arguments, std::ostream& out) {
  out << "dry run: trace " << job.resolved.scene.name << " (" << job.resolved.scene.source << ")\n"
      << "  parameters: "
      << (job.resolved.params.specs().empty() ? "none" : job.resolved.params.summary()) << "\n"
      << "  steps: 0.." << job.resolved.steps << ", every " << arguments.every << ": "
      << job.samples << " samples of the moving bodies (" << job.moving << " at the start)\n"
      << "  writes: " << (job.format == TraceFormat::Json ? "JSON" : "CSV")
      << " to standard output\n"
      << "nothing was run or written\n";
}

/// Writes the trace of `job` to `out`.
void trace_scene(TraceJob& job, std::int64_t every, std::ostream& out) {
  const std::string text = trace_run(*job.run, job.resolved.steps, every, job.format);
  warn_divergences(*job.run);
  out << text;
}

}  // namespace

Command add_trace_command(CLI::App& program, const ProgramOptions&) {
  auto trace = std::make_shared<TraceArguments>();
  CLI::App* command = program.add_subcommand(
      "trace", "print per-step body states (step,t,body,x,y,angle,vx,vy,omega,contacts,energy)");
  add_scene_options(*command, trace->scene, true);
  command->add_option("--steps,-n", trace->scene.steps, "steps to simulate (default: the scene's)")
      ->check(whole_number_check());
  command->add_option("--every,-k", trace->every, "sample every k-th step")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_option("--format", trace->format, "csv or json")->capture_default_str();

  Command result;
  result.parser = command;
  result.dry_run = [trace](std::ostream& out) { print_trace_plan(prepare_trace(*trace), *trace, out); };
  result.run = [trace](std::ostream& out) {
    TraceJob job = prepare_trace(*trace);
    trace_scene(job, trace->every, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos
