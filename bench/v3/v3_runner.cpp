// bench_v3_runner_sse2 / bench_v3_runner_avx2: one of bench_compare's scenes stepped by Box2D v3
// (the commit and vector width baked in at build time, bench/v3.cmake), single-threaded, with
// v3's defaults (4 sub-steps of 1/60 s, continuous on) and bench_compare's world: gravity
// -10 m/s^2, sleeping off. The bodies are the very ones impulse2d steps (compare_scene.cpp),
// copied into v3: boxes as b2MakeBox (as v3's own benchmark makes them), other polygons from
// their hull, circles. `warmup` untimed steps, then `steps` each timed alone (CPU time of the
// thread, the same loop that times impulse2d: v3_protocol.h), the heap the world holds then
// (`heap_in_use` after the steps less before building); then the final states are judged as
// bench_compare judges them. Prints one line (format_runner_line) on stdout and nothing
// else; errors go to stderr (exit 1, bad arguments exit 2). bench_v3 runs it.
//
// Usage: bench_v3_runner_<width> --scene NAME --steps N [--warmup W]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/v3/v3_protocol.h"
#include "box2d/box2d.h"

#ifndef IMPULSE2D_V3_COMMIT
#error "IMPULSE2D_V3_COMMIT (the Box2D v3 commit) is set by bench/v3.cmake"
#endif
#ifndef IMPULSE2D_V3_WIDTH
#error "IMPULSE2D_V3_WIDTH (sse2 or avx2) is set by bench/v3.cmake"
#endif

using namespace impulse2d;

namespace {

// True when `polygon` is an unrounded rectangle centred on the body origin, unrotated (what
// make_oriented_box makes); its half extents then go into `half`.
bool centred_rectangle(const Polygon& polygon, b2Vec2& half) {
  if (polygon.count != 4 || polygon.rounding != 0.0f) return false;
  float hx = 0.0f;
  float hy = 0.0f;
  for (int i = 0; i < 4; ++i) {
    hx = std::fmax(hx, std::fabs(polygon.vertices[static_cast<std::size_t>(i)].x));
    hy = std::fmax(hy, std::fabs(polygon.vertices[static_cast<std::size_t>(i)].y));
  }
  for (int i = 0; i < 4; ++i) {
    const vec2 v = polygon.vertices[static_cast<std::size_t>(i)];
    if (std::fabs(v.x) != hx || std::fabs(v.y) != hy) return false;
  }
  half = {hx, hy};
  return hx > 0.0f && hy > 0.0f;
}

void add_shape(b2BodyId body, const compare::BodySpec& spec) {
  b2ShapeDef shape_def = b2DefaultShapeDef();
  shape_def.density = spec.def.material.density;
  shape_def.material.friction = spec.def.material.dynamic_friction;
  shape_def.material.restitution = spec.def.material.restitution;
  switch (spec.shape.type()) {
    case ShapeType::Circle: {
      const b2Circle circle{{0.0f, 0.0f}, spec.shape.circle().radius};
      b2CreateCircleShape(body, &shape_def, &circle);
      return;
    }
    case ShapeType::Polygon: {
      const Polygon& source = spec.shape.polygon();
      b2Vec2 half{};
      if (centred_rectangle(source, half)) {
        const b2Polygon box = b2MakeBox(half.x, half.y);
        b2CreatePolygonShape(body, &shape_def, &box);
        return;
      }
      b2Vec2 points[max_polygon_vertices];
      for (int i = 0; i < source.count; ++i) {
        points[i] = {source.vertices[static_cast<std::size_t>(i)].x, source.vertices[static_cast<std::size_t>(i)].y};
      }
      const b2Hull hull = b2ComputeHull(points, source.count);
      if (hull.count == 0) throw std::runtime_error("a polygon of the scene has no hull in Box2D v3");
      const b2Polygon polygon = b2MakePolygon(&hull, source.rounding);
      b2CreatePolygonShape(body, &shape_def, &polygon);
      return;
    }
    default:
      throw std::runtime_error("the runner copies circles and polygons only");
  }
}

// The scene in a new v3 world; `bodies` gets the handles in creation order.
b2WorldId build(const compare::CompareScene& scene, std::vector<b2BodyId>& bodies) {
  b2WorldDef world_def = b2DefaultWorldDef();
  world_def.gravity = {0.0f, -10.0f};
  world_def.enableSleep = false;
  world_def.workerCount = 1;
  const b2WorldId world = b2CreateWorld(&world_def);
  bodies.clear();
  bodies.reserve(scene.bodies.size());
  for (const compare::BodySpec& spec : scene.bodies) {
    b2BodyDef body_def = b2DefaultBodyDef();
    body_def.type = spec.def.type == BodyType::Static      ? b2_staticBody
                    : spec.def.type == BodyType::Kinematic ? b2_kinematicBody
                                                           : b2_dynamicBody;
    body_def.position = {spec.def.position.x, spec.def.position.y};
    body_def.rotation = b2MakeRot(spec.def.angle);
    body_def.linearVelocity = {spec.def.linear_velocity.x, spec.def.linear_velocity.y};
    body_def.angularVelocity = spec.def.angular_velocity;
    body_def.enableSleep = false;
    const b2BodyId body = b2CreateBody(world, &body_def);
    add_shape(body, spec);
    bodies.push_back(body);
  }
  return world;
}

void read_states(const std::vector<b2BodyId>& bodies, std::vector<lab::BodyState>& states) {
  states.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const b2Pos position = b2Body_GetPosition(bodies[i]);
    const b2Vec2 velocity = b2Body_GetLinearVelocity(bodies[i]);
    lab::BodyState& state = states[i];
    state.position = {static_cast<float>(position.x), static_cast<float>(position.y)};
    state.angle = b2Rot_GetAngle(b2Body_GetRotation(bodies[i]));
    state.velocity = {velocity.x, velocity.y};
    state.angular_velocity = b2Body_GetAngularVelocity(bodies[i]);
    state.mass = b2Body_GetMass(bodies[i]);
    state.dynamic = b2Body_GetType(bodies[i]) == b2_dynamicBody;
  }
}

int usage(const std::string& message) {
  std::fprintf(stderr, "bench_v3_runner_%s: %s\nusage: bench_v3_runner_%s --scene NAME --steps N [--warmup W]\n",
               IMPULSE2D_V3_WIDTH, message.c_str(), IMPULSE2D_V3_WIDTH);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_name;
  int steps = -1;
  int warmup = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return usage("unknown argument or missing value: " + arg);
    const std::string value = argv[++i];
    if (arg == "--scene") {
      scene_name = value;
    } else if (arg == "--steps" || arg == "--warmup") {
      const int number = bench_v3::parse_count(value, arg == "--steps" ? 1 : 0);
      if (number < 0) return usage(arg + " wants a whole number, not '" + value + "'");
      (arg == "--steps" ? steps : warmup) = number;
    } else {
      return usage("unknown argument " + arg);
    }
  }
  if (scene_name.empty() || steps < 0) return usage("--scene and --steps are required");
  const std::string width = IMPULSE2D_V3_WIDTH;
  if (width == "avx2" && !__builtin_cpu_supports("avx2")) {
    std::fprintf(stderr, "bench_v3_runner_avx2: this CPU has no AVX2\n");
    return 1;
  }
  try {
    const compare::CompareScene scene = bench_v3::scene_by_name(scene_name);
    std::vector<b2BodyId> bodies;
    const double heap_before = bench_v3::heap_in_use();
    const b2WorldId world = build(scene, bodies);
    const float time_step = 1.0f / 60.0f;
    const int substeps = 4;
    const std::vector<double> times =
        bench_v3::timed_steps([&] { b2World_Step(world, time_step, substeps); }, warmup, steps);
    const double heap_after = bench_v3::heap_in_use();
    bench_v3::RunResult result;
    result.scene = scene_name;
    result.width = width;
    result.commit = IMPULSE2D_V3_COMMIT;
    result.steps = steps;
    result.warmup = warmup;
    result.median_ms = bench_v3::median(times);
    result.min_ms = *std::min_element(times.begin(), times.end());
    result.heap_bytes = heap_after - heap_before;
    std::vector<lab::BodyState> states;
    read_states(bodies, states);
    bench_v3::judge(scene, states, result);
    b2DestroyWorld(world);
    std::printf("%s\n", bench_v3::format_runner_line(result).c_str());
    return std::fflush(stdout) == 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_v3_runner_%s: %s\n", IMPULSE2D_V3_WIDTH, error.what());
    return 1;
  }
}
