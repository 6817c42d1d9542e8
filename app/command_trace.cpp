/// @file command_trace.cpp
/// `impulse2d trace`: per-step body states (or, with --events, contact and sensor events) of a
/// run as CSV or JSON; --save-state / --load-state save the world after the run and start it
/// from a saved one.
#include <CLI/CLI.hpp>
#include <memory>

#include "app/command.h"
#include "app/scene_command.h"
#include "app/state_file.h"
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
  bool events = false;         ///< print events instead of body states
  std::string save_state;      ///< file to write the world to after the run, or empty
  std::string load_state;      ///< file to start the world from, or empty
};

/// A trace, checked and ready: what `trace_scene` runs and `print_trace_plan` shows.
struct TraceJob {
  ResolvedScene resolved;                 ///< the scene, its parameters and length
  TraceFormat format = TraceFormat::Csv;  ///< csv or json
  std::int64_t samples = 0;               ///< steps printed: 0, k, 2k, ... and the last
  std::int64_t moving = 0;                ///< bodies that are not static, one row each
  std::unique_ptr<SceneRun> run;          ///< the run, built (and loaded), not yet stepped
  std::uint64_t fingerprint = 0;          ///< the scene's, for --save-state
  std::int64_t first_step = 0;            ///< the run's step count before it runs
};

/// Every check a trace makes before any work; the run and --dry-run both start here. Throws
/// `UsageError`.
TraceJob prepare_trace(const TraceArguments& arguments) {
  TraceJob job;
  // The events are checked against the run's true end once a loaded state gave its start;
  // a run saved for later may stop before some of them (the continuation applies them).
  job.resolved = resolve(arguments.scene, false);
  if (arguments.format == "json") {
    job.format = TraceFormat::Json;
  } else if (arguments.format != "csv") {
    throw UsageError("--format '" + arguments.format + "': expected csv or json");
  }
  if (arguments.every < 1) {
    throw UsageError("--every " + std::to_string(arguments.every) + ": must be at least 1");
  }
  job.run = start_run(job.resolved, arguments.scene);
  job.fingerprint = scene_fingerprint(*job.run);
  if (!arguments.load_state.empty()) load_state_file(arguments.load_state, *job.run);
  job.first_step = job.run->step_count();
  if (arguments.save_state.empty()) check_events_in_run(job.resolved, job.first_step + job.resolved.steps);
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
      << "  steps: " << job.first_step << ".." << job.first_step + job.resolved.steps << ", every " << arguments.every << ": "
      << job.samples << " samples of the moving bodies (" << job.moving << " at the start)\n"
      << "  writes: " << (job.format == TraceFormat::Json ? "JSON" : "CSV")
      << (arguments.events ? " events" : "") << " to standard output"
      << (arguments.save_state.empty() ? "" : ", the world after the run to " + arguments.save_state)
      << "\n"
      << "nothing was run or written\n";
}

/// Writes the trace of `job` to `out`.
void trace_scene(TraceJob& job, const TraceArguments& arguments, std::ostream& out) {
  const std::int64_t last = job.first_step + job.resolved.steps;
  std::string text;
  if (arguments.events) {
    text = trace_events(*job.run, last, job.format);
  } else {
    // (From a saved state at step s the samples are the multiples of k from s on and the
    // last: the rows a run from step 0 prints for those steps, bit for bit.)
    text = trace_run(*job.run, last, arguments.every, job.format);
  }
  warn_divergences(*job.run);
  if (!arguments.save_state.empty()) save_state_file(arguments.save_state, *job.run, job.fingerprint);
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
  command->add_flag("--events", trace->events,
                    "print contact and sensor events "
                    "(step,kind,shape_a,shape_b,body_a,body_b,x,y,nx,ny,speed) instead of body states");
  command->add_option("--save-state", trace->save_state,
                      "write the world after the run to this file (for --load-state)");
  command->add_option("--load-state", trace->load_state,
                      "start from a world saved by --save-state of the same scene; --steps "
                      "counts the steps after it");

  Command result;
  result.parser = command;
  result.dry_run = [trace](std::ostream& out) { print_trace_plan(prepare_trace(*trace), *trace, out); };
  result.run = [trace](std::ostream& out) {
    TraceJob job = prepare_trace(*trace);
    trace_scene(job, *trace, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos
