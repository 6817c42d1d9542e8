/// @file trace_writer.cpp
#include "scene/trace_writer.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "scene/run_limits.h"
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

/// JSON whose floats are `float` (dumped in the shortest text that reads back the same float)
/// and whose objects keep their keys in insertion order.
using FloatJson = nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                                       std::uint64_t, float>;

/// One event row: the fields every kind has, and the hit's point, normal and speed.
struct EventRow {
  const char* kind = "";
  std::uint32_t shape_a = 0, shape_b = 0, body_a = 0, body_b = 0;
  bool has_point = false;
  float values[5] = {0, 0, 0, 0, 0};  // x, y, nx, ny, speed
};

void append_event(std::int64_t step, const EventRow& row, TraceFormat format, std::string& out,
                  bool first) {
  static const char* const value_names[] = {"x", "y", "nx", "ny", "speed"};
  if (format == TraceFormat::Csv) {
    out += std::to_string(step) + "," + row.kind + "," + std::to_string(row.shape_a) + "," +
           std::to_string(row.shape_b) + "," + std::to_string(row.body_a) + "," +
           std::to_string(row.body_b);
    for (const float value : row.values) {
      out += ",";
      if (row.has_point) out += FloatJson(value).dump();
    }
    out += "\n";
    return;
  }
  FloatJson object = FloatJson::object();
  object["step"] = step;
  object["kind"] = row.kind;
  object["shape_a"] = row.shape_a;
  object["shape_b"] = row.shape_b;
  object["body_a"] = row.body_a;
  object["body_b"] = row.body_b;
  if (row.has_point) {
    for (int i = 0; i < 5; ++i) object[value_names[i]] = row.values[i];
  }
  out += first ? "\n    " : ",\n    ";
  out += object.dump();
}

/// The last step's events as rows, in the documented order.
std::vector<EventRow> event_rows(const World& world) {
  std::vector<EventRow> rows;
  const ContactEvents& contacts = world.contact_events();
  for (const ContactBeginTouchEvent& e : contacts.begin) {
    rows.push_back({"begin_touch", e.shape_a.index, e.shape_b.index, e.body_a.index, e.body_b.index});
  }
  for (const ContactEndTouchEvent& e : contacts.end) {
    rows.push_back({"end_touch", e.shape_a.index, e.shape_b.index, e.body_a.index, e.body_b.index});
  }
  for (const ContactHitEvent& e : contacts.hit) {
    rows.push_back({"hit", e.shape_a.index, e.shape_b.index, e.body_a.index, e.body_b.index, true,
                    {e.point.x, e.point.y, e.normal.x, e.normal.y, e.approach_speed}});
  }
  const SensorEvents& sensors = world.sensor_events();
  for (const SensorBeginTouchEvent& e : sensors.begin) {
    rows.push_back({"sensor_begin", e.sensor_shape.index, e.visitor_shape.index,
                    e.sensor_body.index, e.visitor_body.index});
  }
  for (const SensorEndTouchEvent& e : sensors.end) {
    rows.push_back({"sensor_end", e.sensor_shape.index, e.visitor_shape.index,
                    e.sensor_body.index, e.visitor_body.index});
  }
  return rows;
}

}  // namespace

std::string trace_events(SceneRun& run, std::int64_t steps, TraceFormat format) {
  std::string out;
  if (format == TraceFormat::Csv) {
    out = "step,kind,shape_a,shape_b,body_a,body_b,x,y,nx,ny,speed\n";
  } else {
    out = "{\n  \"scene\": " + nlohmann::json(run.scene().name).dump() +
          ",\n  \"time_step\": " + FloatJson(run.world().settings().time_step).dump() +
          ",\n  \"events\": [";
  }
  std::int64_t count = 0;
  while (run.step_count() < steps) {
    run.step();
    for (const EventRow& row : event_rows(run.world())) {
      if (++count > limits::max_trace_rows) {
        throw UsageError("trace --events: more than " + std::to_string(limits::max_trace_rows) +
                         " events by step " + std::to_string(run.step_count()) +
                         " (lower --steps)");
      }
      append_event(run.step_count(), row, format, out, count == 1);
    }
  }
  if (format == TraceFormat::Json) out += count == 0 ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

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
