#pragma once
/// @file trace_writer.h
/// Per-step body states of a run as CSV or JSON, for plotting and for checking a scene
/// against an exact answer.

#include <cstdint>
#include <string>

#include "scene/scene_run.h"

namespace impulse2d::demos {

/// Output format of a trace.
enum class TraceFormat {
  Csv,   ///< header `step,t,body,x,y,angle,vx,vy,omega,contacts,energy`, one row per body
  Json,  ///< {"scene", "time_step", "samples": [{"step", "t", "contacts", "energy", "bodies"}]}
};

/// Steps `run` to `steps` and samples steps 0, every, 2 every, ... up to `steps` (and `steps`
/// itself). Each sample lists every non-static body (by slot index) with its position (m),
/// angle (rad), velocity (m/s) and angular velocity (rad/s), plus the world's touching pairs
/// (`contacts`) and total mechanical energy (`energy`, J: kinetic + rotational + gravitational
/// potential relative to y = 0 along gravity). Floats are written with 9 significant digits,
/// enough to read back the exact float. Throws `UsageError` unless steps >= 0 and every >= 1.
std::string trace_run(SceneRun& run, std::int64_t steps, std::int64_t every, TraceFormat format);

/// Steps `run` until its step count reaches `steps` and lists every contact and sensor event
/// of those steps, by step (the step's count after it: 1 = the first), then kind (begin_touch,
/// end_touch, hit, sensor_begin, sensor_end), then the world's order. CSV: header
/// `step,kind,shape_a,shape_b,body_a,body_b,x,y,nx,ny,speed`, bodies by slot index (as in the
/// state rows; for sensor events a = the sensor, b = the visitor), shapes by their index on
/// the body, and the point, normal and approach speed only for hits (empty otherwise). JSON:
/// {"scene", "time_step", "events": [{"step", "kind", "shape_a", ..., "speed"}]} without the
/// fields a kind lacks. Floats in the shortest form that reads back the exact float. Throws
/// `UsageError` past `limits::max_trace_rows` events.
std::string trace_events(SceneRun& run, std::int64_t steps, TraceFormat format);

/// Total mechanical energy of the world's dynamic bodies, joules.
double mechanical_energy(const World& world);

/// The world's touching pairs (the trace's `contacts` column).
std::int64_t contact_count(const World& world);

}  // namespace impulse2d::demos
