/// @file trace_writer.cpp
#include "scene/trace_writer.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// `value` with 9 significant digits (round-trips a float); in JSON, which has no NaN or
/// infinity, a non-finite value is `null`.
std::string number(double value, TraceFormat format = TraceFormat::Csv) {
  if (format == TraceFormat::Json && !std::isfinite(value)) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

void append_sample(const World& world, TraceFormat format, std::string& out, bool first_sample) {
  const std::string step = std::to_string(world.step_count());
  const std::string time = number(world.time(), format);
  const std::string contacts = std::to_string(contact_count(world));
  const std::string energy = number(mechanical_energy(world), format);
  if (format == TraceFormat::Json) {
    out += first_sample ? "\n    " : ",\n    ";
    out += "{\"step\": " + step + ", \"t\": " + time + ", \"contacts\": " + contacts +
           ", \"energy\": " + energy + ", \"bodies\": [";
  }
  bool first_body = true;
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    if (body.type == BodyType::Static) continue;
    const std::string values[] = {number(body.transform.position.x, format),
                                  number(body.transform.position.y, format),
                                  number(body.angle, format),
                                  number(body.linear_velocity.x, format),
                                  number(body.linear_velocity.y, format),
                                  number(body.angular_velocity, format)};
    if (format == TraceFormat::Csv) {
      out += step + "," + time + "," + std::to_string(id.index);
      for (const std::string& value : values) out += "," + value;
      out += "," + contacts + "," + energy + "\n";
    } else {
      const char* names[] = {"x", "y", "angle", "vx", "vy", "omega"};
      out += first_body ? "\n      {" : ",\n      {";
      out += "\"body\": " + std::to_string(id.index);
      for (int i = 0; i < 6; ++i) out += std::string(", \"") + names[i] + "\": " + values[i];
      out += "}";
    }
    first_body = false;
  }
  if (format == TraceFormat::Json) out += first_body ? "]}" : "\n    ]}";
}

}  // namespace

double mechanical_energy(const World& world) {
  const vec2 gravity = world.settings().gravity;
  double energy = 0.0;
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    if (body.type != BodyType::Dynamic) continue;
    const double speed_squared = glm::dot(body.linear_velocity, body.linear_velocity);
    const double spin = static_cast<double>(body.angular_velocity);
    const double height_work = glm::dot(gravity * body.gravity_scale, body.transform.position);
    energy += 0.5 * body.mass * speed_squared + 0.5 * body.inertia * spin * spin -
              body.mass * height_work;
  }
  return energy;
}

std::int64_t contact_count(const World& world) {
  return static_cast<std::int64_t>(world.contacts().size());
}

std::string trace_run(SceneRun& run, std::int64_t steps, std::int64_t every, TraceFormat format) {
  if (steps < 0) throw UsageError("--steps must be >= 0");
  if (every < 1) throw UsageError("--every must be >= 1");
  std::string out;
  if (format == TraceFormat::Csv) {
    out = "step,t,body,x,y,angle,vx,vy,omega,contacts,energy\n";
  } else {
    out = "{\n  \"scene\": " + nlohmann::json(run.scene().name).dump() +
          ",\n  \"time_step\": " + number(run.world().settings().time_step) + ",\n  \"samples\": [";
  }
  bool first = true;
  while (true) {
    const std::int64_t step = run.step_count();
    if (step % every == 0 || step == steps) {
      append_sample(run.world(), format, out, first);
      first = false;
    }
    if (step >= steps) break;
    run.step();
  }
  if (format == TraceFormat::Json) out += "\n  ]\n}\n";
  return out;
}

}  // namespace impulse2d::demos
