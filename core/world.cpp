#include "core/world.h"

#include "core/error.h"
#include "core/solver/integrate.h"
#include "core/solver/step_solver.h"
#include "core/solver/world_state.h"
#include "core/world_events.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace impulse2d {

namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

std::string describe(BodyId id) {
  return "body {index " + std::to_string(id.index) + ", generation " + std::to_string(id.generation) + "}";
}

// Drops every contact of `contacts` that involves body `id`.
void erase_contacts_of(std::vector<Contact>& contacts, BodyId id) {
  auto touches = [&id](const Contact& contact) { return contact.body_a == id || contact.body_b == id; };
  contacts.erase(std::remove_if(contacts.begin(), contacts.end(), touches), contacts.end());
}

void require_finite(float value, const char* caller, const char* name) {
  if (!std::isfinite(value)) throw Error(std::string(caller) + ": " + name + " is not finite");
}

void require_finite(vec2 value, const char* caller, const char* name) {
  if (!is_finite(value)) throw Error(std::string(caller) + ": " + name + " is not finite");
}

bool is_living(const WorldState& world, BodyId id) {
  return !id.is_null() && id.index < world.bodies.size() && world.alive[id.index] &&
         world.bodies[id.index].id.generation == id.generation;
}

Body& checked_body(WorldState& world, BodyId id, const char* caller) {
  if (!is_living(world, id)) {
    throw Error(std::string(caller) + ": " + describe(id) +
                (id.is_null() ? " is a null handle" : " is stale or was never created"));
  }
  return world.bodies[id.index];
}

// One walk over the bodies after the solve: forces cleared, diverged bodies put back where the
// step began (and reported), bounds refreshed and covered by the broad phase (queries search
// its trees; the next step's contacts start from these bounds), awake bodies counted.
// With a `pool`, the bounds are computed side by side on its workers between a first walk
// (forces, diverged bodies) and a last one (broad phase, count), in slot order as with one.
void finish_bodies(WorldState& world, WorkerPool* pool) {
  auto restore_diverged = [&world](Body& body) {
    const bool finite = is_finite(body.transform.position) && std::isfinite(body.angle) &&
                        is_finite(body.linear_velocity) && std::isfinite(body.angular_velocity);
    if (finite) return;
    body.transform = Transform{body.previous_position, Rotation::from_angle(body.previous_angle)};
    body.angle = body.previous_angle;
    body.linear_velocity = vec2(0.0f);
    body.angular_velocity = 0.0f;
    body.awake = false;
    world.diverged_bodies.push_back(body.id);
  };
  if (pool != nullptr) {
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
      Body& body = world.bodies[i];
      body.force = vec2(0.0f);
      body.torque = 0.0f;
      if (world.alive[i]) restore_diverged(body);
    }
    update_bounds(world.bodies, world.alive, pool);
    for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
      if (!world.alive[i]) continue;
      const Body& body = world.bodies[i];
      world.broad_phase.cover(i, body.aabb);
      if (body.awake && body.type != BodyType::Static) ++world.stats.awake_body_count;
    }
    world.bounds_current = true;
    return;
  }
  for (std::uint32_t i = 0; i < world.bodies.size(); ++i) {
    Body& body = world.bodies[i];
    body.force = vec2(0.0f);
    body.torque = 0.0f;
    if (!world.alive[i]) continue;
    restore_diverged(body);
    body.aabb = body_aabb(body);
    world.broad_phase.cover(i, body.aabb);
    if (body.awake && body.type != BodyType::Static) ++world.stats.awake_body_count;
  }
  world.bounds_current = true;
}

}  // namespace

World::World(const WorldSettings& settings) : state_(std::make_unique<WorldState>()) {
  validate_settings(settings);
  state_->settings = settings;
}

World::World(const World& other) : state_(std::make_unique<WorldState>(*other.state_)) {}

World& World::operator=(const World& other) {
  if (this != &other) state_ = std::make_unique<WorldState>(*other.state_);
  return *this;
}

World::World(World&& other) noexcept = default;
World& World::operator=(World&& other) noexcept = default;
World::~World() = default;

const WorldSettings& World::settings() const { return state_->settings; }
int World::body_count() const { return state_->living_body_count; }
float World::interpolation_alpha() const { return state_->accumulator / state_->settings.time_step; }
double World::time() const { return state_->time; }
std::int64_t World::step_count() const { return state_->step_count; }
const std::vector<Contact>& World::contacts() const { return state_->contacts; }
const std::vector<Contact>& World::sleeping_contacts() const { return state_->sleeping_contacts; }
void World::set_contact_filter(ContactFilter filter) { state_->contact_filter = std::move(filter); }
const StepStats& World::stats() const { return state_->stats; }
const std::vector<BodyId>& World::diverged_bodies() const { return state_->diverged_bodies; }
const ContactEvents& World::contact_events() const { return state_->events.contact; }
const SensorEvents& World::sensor_events() const { return state_->events.sensor; }
float World::hit_event_threshold() const { return state_->events.hit_event_threshold; }

void World::set_hit_event_threshold(float speed) {
  if (!(std::isfinite(speed) && speed >= 0.0f)) {
    throw Error("World::set_hit_event_threshold: speed must be finite and >= 0 (got " +
                std::to_string(speed) + ")");
  }
  state_->events.hit_event_threshold = speed;
}

namespace {
// Counts the living bodies that ask for each kind of event (`sign` +1 on creation, -1 on removal).
void count_event_flags(WorldEvents& events, const Body& body, int sign) {
  if (body.enable_contact_events) events.contact_event_bodies += sign;
  if (body.enable_hit_events) events.hit_event_bodies += sign;
  if (body.is_sensor || body.has_sensor_shapes) events.sensor_bodies += sign;
}
}  // namespace

void World::set_settings(const WorldSettings& settings) {
  validate_settings(settings);
  state_->settings = settings;
}

void World::set_gravity(vec2 gravity) {
  WorldSettings changed = state_->settings;
  changed.gravity = gravity;
  set_settings(changed);
}

void World::set_time_step(float time_step) {
  WorldSettings changed = state_->settings;
  changed.time_step = time_step;
  set_settings(changed);
}

BodyId World::create_body(const BodyDef& def, const Shape& shape) {
  const char* caller = "World::create_body";
  require_finite(def.position, caller, "position");
  require_finite(def.angle, caller, "angle");
  require_finite(def.linear_velocity, caller, "linear_velocity");
  require_finite(def.angular_velocity, caller, "angular_velocity");
  require_finite(def.gravity_scale, caller, "gravity_scale");
  if (!(std::isfinite(def.linear_damping) && def.linear_damping >= 0.0f)) {
    throw Error("World::create_body: linear_damping must be finite and >= 0");
  }
  if (!(std::isfinite(def.angular_damping) && def.angular_damping >= 0.0f)) {
    throw Error("World::create_body: angular_damping must be finite and >= 0");
  }
  validate_material(def.material, "World::create_body: material");
  validate_shape(shape, "World::create_body");
  if (def.type == BodyType::Dynamic && shape.type() == ShapeType::Segment) {
    throw Error("World::create_body: a segment has no area and so no mass: a dynamic body "
                "cannot be only a segment (make it static or kinematic, or use a capsule)");
  }
  if (def.type != BodyType::Static && shape.type() == ShapeType::Segment &&
      shape.segment().one_sided) {
    throw Error("World::create_body: a chain is level geometry: only a static body may hold a "
                "chain link (make the body static, or use segments or capsules)");
  }
  if (def.type == BodyType::Dynamic && !(def.material.density > 0.0f)) {
    throw Error("World::create_body: a dynamic body needs material density > 0 (got " +
                std::to_string(def.material.density) + ")");
  }

  std::uint32_t index;
  if (!state_->free_slots.empty()) {
    // Lowest free slot first, so the slot order is the same for the same calls.
    auto lowest = std::min_element(state_->free_slots.begin(), state_->free_slots.end());
    index = *lowest;
    state_->free_slots.erase(lowest);
  } else {
    index = static_cast<std::uint32_t>(state_->bodies.size());
    state_->bodies.emplace_back();
    state_->alive.push_back(0);
  }
  const std::uint32_t generation = state_->bodies[index].id.generation + 1;
  Body body;
  body.id = BodyId{index, generation};
  body.type = def.type;
  body.shape = shape;
  if (shape.type() == ShapeType::Polygon) {
    // Made here, not trusted from the caller: vertices edited after `make_polygon` would
    // leave a stale cached radius.
    Polygon polygon = shape.polygon();
    polygon.radius = farthest_vertex_distance(polygon);
    body.shape = polygon;
  }
  body.extent = shape_extent(body.shape);
  body.rounding = shape_rounding(body.shape);
  body.material = def.material;
  const bool rotates = shape.type() != ShapeType::Box && !def.fixed_rotation;
  body.angle = rotates ? def.angle : 0.0f;
  body.transform = Transform{def.position, Rotation::from_angle(body.angle)};
  body.previous_position = def.position;
  body.previous_angle = body.angle;
  body.linear_velocity = def.linear_velocity;
  body.angular_velocity = rotates ? def.angular_velocity : 0.0f;
  if (def.type == BodyType::Dynamic) {
    const MassData mass = compute_mass(shape, def.material.density);
    body.mass = mass.mass;
    body.inverse_mass = 1.0f / mass.mass;
    body.inertia = mass.inertia;
    body.inverse_inertia = (rotates && mass.inertia > 0.0f) ? 1.0f / mass.inertia : 0.0f;
  }
  body.gravity_scale = def.gravity_scale;
  body.linear_damping = def.linear_damping;
  body.angular_damping = def.angular_damping;
  body.fixed_rotation = !rotates;
  body.is_bullet = def.is_bullet;
  body.speculative = def.speculative;
  body.collision_layers = def.collision_layers;
  body.user_data = def.user_data;
  body.enable_contact_events = def.enable_contact_events;
  body.enable_hit_events = def.enable_hit_events;
  body.is_sensor = def.is_sensor;
  body.sensor_detects_static = def.sensor_detects_static;
  body.enable_sensor_events = def.enable_sensor_events;
  count_event_flags(state_->events, body, +1);
  body.aabb = body_aabb(body);
  state_->bodies[index] = body;
  state_->alive[index] = 1;
  state_->broad_phase.add_body(index, body.type, body.aabb);
  ++state_->living_body_count;
  return body.id;
}

void World::remove_body(BodyId id) {
  count_event_flags(state_->events, checked_body(*state_, id, "World::remove_body"), -1);
  end_events_of_removed_body(*state_, id);
  state_->alive[id.index] = 0;
  state_->broad_phase.remove_body(id.index);
  state_->free_slots.push_back(id.index);
  --state_->living_body_count;
  // Forget its contacts now so nothing refers to the dead slot.
  erase_contacts_of(state_->contacts, id);
  erase_contacts_of(state_->sleeping_contacts, id);
  if (state_->living_joint_count > 0) state_->destroy_joints_of(id);
}

bool World::is_valid(BodyId id) const { return is_living(*state_, id); }

BodyView World::body(BodyId id) const { return view_of(checked_body(*state_, id, "World::body")); }

std::vector<BodyId> World::body_ids() const {
  std::vector<BodyId> ids;
  ids.reserve(static_cast<std::size_t>(state_->living_body_count));
  for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
    if (state_->alive[i]) ids.push_back(state_->bodies[i].id);
  }
  return ids;
}

void World::set_transform(BodyId id, vec2 position, float angle) {
  const char* caller = "World::set_transform";
  require_finite(position, caller, "position");
  require_finite(angle, caller, "angle");
  Body& body = checked_body(*state_, id, caller);
  if (body.fixed_rotation) angle = 0.0f;
  body.transform = Transform{position, Rotation::from_angle(angle)};
  body.angle = angle;
  body.previous_position = position;
  body.previous_angle = angle;
  body.aabb = body_aabb(body);
  state_->broad_phase.cover(id.index, body.aabb);
  body.awake = true;
  erase_contacts_of(state_->sleeping_contacts, id);  // its set-aside contacts no longer describe where it is
}

void World::set_linear_velocity(BodyId id, vec2 velocity) {
  require_finite(velocity, "World::set_linear_velocity", "velocity");
  Body& body = checked_body(*state_, id, "World::set_linear_velocity");
  if (body.type == BodyType::Static) return;
  body.linear_velocity = velocity;
  body.awake = true;
}

void World::set_angular_velocity(BodyId id, float angular_velocity) {
  require_finite(angular_velocity, "World::set_angular_velocity", "angular_velocity");
  Body& body = checked_body(*state_, id, "World::set_angular_velocity");
  if (body.type == BodyType::Static || body.fixed_rotation) return;
  body.angular_velocity = angular_velocity;
  body.awake = true;
}

void World::set_gravity_scale(BodyId id, float scale) {
  require_finite(scale, "World::set_gravity_scale", "scale");
  checked_body(*state_, id, "World::set_gravity_scale").gravity_scale = scale;
}

void World::set_material(BodyId id, const Material& material) {
  validate_material(material, "World::set_material: material");
  Body& body = checked_body(*state_, id, "World::set_material");
  if (body.compound) {
    if (body.type == BodyType::Dynamic && !(material.density > 0.0f)) {
      throw Error("World::set_material: a dynamic body needs material density > 0 (got " +
                  std::to_string(material.density) + ")");
    }
    for (BodyShape& part : body.children) part.material = material;
    recentre_compound(body);
    state_->broad_phase.cover(id.index, body.aabb);
  } else if (body.type == BodyType::Dynamic) {
    if (!(material.density > 0.0f)) {
      throw Error("World::set_material: a dynamic body needs material density > 0 (got " +
                  std::to_string(material.density) + ")");
    }
    const MassData mass = compute_mass(body.shape, material.density);
    body.mass = mass.mass;
    body.inverse_mass = 1.0f / mass.mass;
    body.inertia = mass.inertia;
    body.inverse_inertia = (!body.fixed_rotation && mass.inertia > 0.0f) ? 1.0f / mass.inertia : 0.0f;
  }
  body.material = material;
  body.awake = true;
}

void World::apply_force(BodyId id, vec2 force, vec2 world_point) {
  require_finite(force, "World::apply_force", "force");
  require_finite(world_point, "World::apply_force", "world_point");
  Body& body = checked_body(*state_, id, "World::apply_force");
  if (body.type != BodyType::Dynamic) return;
  body.force += force;
  body.torque += cross(world_point - body.transform.position, force);
  body.awake = true;
}

void World::apply_force_to_center(BodyId id, vec2 force) {
  require_finite(force, "World::apply_force_to_center", "force");
  Body& body = checked_body(*state_, id, "World::apply_force_to_center");
  if (body.type != BodyType::Dynamic) return;
  body.force += force;
  body.awake = true;
}

void World::apply_torque(BodyId id, float torque) {
  require_finite(torque, "World::apply_torque", "torque");
  Body& body = checked_body(*state_, id, "World::apply_torque");
  if (body.type != BodyType::Dynamic) return;
  body.torque += torque;
  body.awake = true;
}

void World::apply_linear_impulse(BodyId id, vec2 impulse, vec2 world_point) {
  require_finite(impulse, "World::apply_linear_impulse", "impulse");
  require_finite(world_point, "World::apply_linear_impulse", "world_point");
  Body& body = checked_body(*state_, id, "World::apply_linear_impulse");
  if (body.type != BodyType::Dynamic) return;
  body.linear_velocity += impulse * body.inverse_mass;
  body.angular_velocity += effective_inverse_inertia(body, state_->settings) *
                           cross(world_point - body.transform.position, impulse);
  body.awake = true;
}

void World::apply_angular_impulse(BodyId id, float impulse) {
  require_finite(impulse, "World::apply_angular_impulse", "impulse");
  Body& body = checked_body(*state_, id, "World::apply_angular_impulse");
  if (body.type != BodyType::Dynamic) return;
  body.angular_velocity += effective_inverse_inertia(body, state_->settings) * impulse;
  body.awake = true;
}

void World::set_awake(BodyId id, bool awake) {
  Body& body = checked_body(*state_, id, "World::set_awake");
  if (body.type == BodyType::Static) return;
  body.awake = awake;
  body.sleep_time = 0.0f;
  if (!awake) {
    body.linear_velocity = vec2(0.0f);
    body.angular_velocity = 0.0f;
  }
}

bool World::set_contact_enabled(BodyId a, BodyId b, bool enabled) {
  checked_body(*state_, a, "World::set_contact_enabled");
  checked_body(*state_, b, "World::set_contact_enabled");
  if (b.index < a.index) std::swap(a, b);
  bool found = false;  // every contact of the pair (one per pair of shapes of compound bodies)
  for (std::vector<Contact>* list : {&state_->contacts, &state_->sleeping_contacts}) {
    for (Contact& contact : *list) {
      if (contact.body_a == a && contact.body_b == b) {
        contact.enabled = enabled;  // the next step's narrow phase carries it over
        found = true;
      }
    }
  }
  return found;
}

// ---- the step ---------------------------------------------------------------------------

void World::step() {
  WorldState& world = *state_;
  const Clock::time_point start = Clock::now();
  world.stats = StepStats{};
  world.diverged_bodies.clear();
  // Null: one worker and no task system.
  WorkerPool* const pool = world.workers.get(world.settings.worker_count, world.settings.task_system);
  parallel_for(pool, world.bodies.size(), 512, [&world](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Body& body = world.bodies[i];
      body.previous_position = body.transform.position;
      body.previous_angle = body.angle;
    }
  });
  begin_step_events(world, pool);
  if (!world.solver || world.solver_method != world.settings.solver) {
    world.solver = make_step_solver(world.settings.solver);
    world.solver_method = world.settings.solver;
  }
  const Clock::time_point solve_start = Clock::now();
  SolverStages stages(world);
  SolverContext context = resolve_solver_context(world.settings);
  context.touch_velocities = touch_velocities(world.events);
  world.wide_contacts.forget_touch_tally();  // a solver that does not visit leaves it invalid
  world.solver->step(stages, context);
  // Whatever the stages did not time themselves is the solver's own work.
  world.stats.solver_ms = elapsed_ms(solve_start) - world.stats.broad_phase_ms -
                          world.stats.narrow_phase_ms - world.stats.integrate_ms -
                          world.stats.position_ms;
  if (world.settings.enable_sleeping) {
    world.sleep_islands.update(world.bodies, world.alive, world.contacts, world.joints,
                               world.joint_alive, world.settings, world.settings.time_step, pool);
  }
  finish_bodies(world, pool);
  collect_step_events(world);
  world.time += static_cast<double>(world.settings.time_step);
  ++world.step_count;
  world.stats.body_count = world.living_body_count;
  world.stats.total_ms = elapsed_ms(start);
}

int World::advance(float frame_time) {
  require_finite(frame_time, "World::advance", "frame_time");
  if (frame_time < 0.0f) throw Error("World::advance: frame_time must be >= 0");
  constexpr float max_frame_time = 0.25f;  // seconds; guards against the spiral of death
  state_->accumulator += std::min(frame_time, max_frame_time);
  int steps = 0;
  while (state_->accumulator >= state_->settings.time_step) {
    step();
    state_->accumulator -= state_->settings.time_step;
    ++steps;
  }
  return steps;
}

std::uint64_t World::state_hash() const {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis
  auto mix_bytes = [&hash](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash ^= bytes[i];
      hash *= 1099511628211ull;  // FNV prime
    }
  };
  for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
    if (!state_->alive[i]) continue;
    const Body& body = state_->bodies[i];
    const std::uint32_t index = static_cast<std::uint32_t>(i);
    const float values[6] = {body.transform.position.x, body.transform.position.y, body.angle,
                             body.linear_velocity.x,    body.linear_velocity.y,    body.angular_velocity};
    mix_bytes(&index, sizeof index);
    mix_bytes(values, sizeof values);
  }
  return hash;
}

}  // namespace impulse2d
