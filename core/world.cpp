#include "core/world.h"

#include "core/error.h"
#include "core/solver/integrate.h"
#include "core/collide/narrow_phase.h"
#include "core/solver/position_correction.h"
#include "core/collide/speculative_reach.h"

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

void validate_shape(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::Circle:
      if (!(std::isfinite(shape.circle.radius) && shape.circle.radius > 0.0f)) {
        throw Error("World::create_body: circle radius must be finite and > 0");
      }
      return;
    case ShapeType::Box:
      if (!(is_finite(shape.box.half_extents) && shape.box.half_extents.x > 0.0f &&
            shape.box.half_extents.y > 0.0f)) {
        throw Error("World::create_body: box half extents must be finite and > 0");
      }
      return;
    case ShapeType::Polygon:
      if (shape.polygon.count < 3 || shape.polygon.count > max_polygon_vertices) {
        throw Error("World::create_body: polygon needs 3..8 vertices (use make_polygon)");
      }
      return;
  }
  throw Error("World::create_body: unknown shape type");
}

}  // namespace

World::World(const WorldSettings& settings) : settings_(settings) { validate_settings(settings_); }

void World::set_settings(const WorldSettings& settings) {
  validate_settings(settings);
  settings_ = settings;
}

void World::set_gravity(vec2 gravity) {
  WorldSettings changed = settings_;
  changed.gravity = gravity;
  set_settings(changed);
}

void World::set_time_step(float time_step) {
  WorldSettings changed = settings_;
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
  validate_shape(shape);
  if (def.type == BodyType::Dynamic && !(def.material.density > 0.0f)) {
    throw Error("World::create_body: a dynamic body needs material density > 0 (got " +
                std::to_string(def.material.density) + ")");
  }

  std::uint32_t index;
  if (!free_slots_.empty()) {
    // Lowest free slot first, so the slot order is the same for the same calls.
    auto lowest = std::min_element(free_slots_.begin(), free_slots_.end());
    index = *lowest;
    free_slots_.erase(lowest);
  } else {
    index = static_cast<std::uint32_t>(bodies_.size());
    bodies_.emplace_back();
    alive_.push_back(0);
  }
  const std::uint32_t generation = bodies_[index].id.generation + 1;
  Body body;
  body.id = BodyId{index, generation};
  body.type = def.type;
  body.shape = shape;
  if (shape.type == ShapeType::Polygon) {
    // Made here, not trusted from the caller: vertices edited after `make_polygon` would
    // leave a stale cached radius.
    body.shape.polygon.radius = farthest_vertex_distance(shape.polygon);
  }
  body.extent = shape_extent(body.shape);
  body.material = def.material;
  const bool rotates = shape.type != ShapeType::Box && !def.fixed_rotation;
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
  body.aabb = compute_aabb(body.shape, body.transform);
  bodies_[index] = body;
  alive_[index] = 1;
  broad_phase_.add_body(index, body.type, body.aabb);
  ++living_body_count_;
  return body.id;
}

void World::remove_body(BodyId id) {
  checked_body(id, "World::remove_body");
  alive_[id.index] = 0;
  broad_phase_.remove_body(id.index);
  free_slots_.push_back(id.index);
  --living_body_count_;
  // Forget its contacts now so nothing refers to the dead slot.
  erase_contacts_of(contacts_, id);
  forget_sleeping_contacts(id);
}

void World::forget_sleeping_contacts(BodyId id) { erase_contacts_of(sleeping_contacts_, id); }

bool World::is_valid(BodyId id) const {
  return !id.is_null() && id.index < bodies_.size() && alive_[id.index] &&
         bodies_[id.index].id.generation == id.generation;
}

Body& World::checked_body(BodyId id, const char* caller) {
  if (!is_valid(id)) {
    throw Error(std::string(caller) + ": " + describe(id) +
                (id.is_null() ? " is a null handle" : " is stale or was never created"));
  }
  return bodies_[id.index];
}

const Body& World::checked_body(BodyId id, const char* caller) const {
  return const_cast<World*>(this)->checked_body(id, caller);
}

const Body& World::body(BodyId id) const { return checked_body(id, "World::body"); }

std::vector<BodyId> World::body_ids() const {
  std::vector<BodyId> ids;
  ids.reserve(static_cast<std::size_t>(living_body_count_));
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (alive_[i]) ids.push_back(bodies_[i].id);
  }
  return ids;
}

void World::set_transform(BodyId id, vec2 position, float angle) {
  const char* caller = "World::set_transform";
  require_finite(position, caller, "position");
  require_finite(angle, caller, "angle");
  Body& body = checked_body(id, caller);
  if (body.fixed_rotation) angle = 0.0f;
  body.transform = Transform{position, Rotation::from_angle(angle)};
  body.angle = angle;
  body.previous_position = position;
  body.previous_angle = angle;
  body.aabb = compute_aabb(body.shape, body.transform);
  broad_phase_.cover(id.index, body.aabb);
  body.awake = true;
  forget_sleeping_contacts(id);  // its set-aside contacts no longer describe where it is
}

void World::set_linear_velocity(BodyId id, vec2 velocity) {
  require_finite(velocity, "World::set_linear_velocity", "velocity");
  Body& body = checked_body(id, "World::set_linear_velocity");
  if (body.type == BodyType::Static) return;
  body.linear_velocity = velocity;
  body.awake = true;
}

void World::set_angular_velocity(BodyId id, float angular_velocity) {
  require_finite(angular_velocity, "World::set_angular_velocity", "angular_velocity");
  Body& body = checked_body(id, "World::set_angular_velocity");
  if (body.type == BodyType::Static || body.fixed_rotation) return;
  body.angular_velocity = angular_velocity;
  body.awake = true;
}

void World::set_gravity_scale(BodyId id, float scale) {
  require_finite(scale, "World::set_gravity_scale", "scale");
  checked_body(id, "World::set_gravity_scale").gravity_scale = scale;
}

void World::set_material(BodyId id, const Material& material) {
  validate_material(material, "World::set_material: material");
  Body& body = checked_body(id, "World::set_material");
  if (body.type == BodyType::Dynamic) {
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
  Body& body = checked_body(id, "World::apply_force");
  if (body.type != BodyType::Dynamic) return;
  body.force += force;
  body.torque += cross(world_point - body.transform.position, force);
  body.awake = true;
}

void World::apply_force_to_center(BodyId id, vec2 force) {
  require_finite(force, "World::apply_force_to_center", "force");
  Body& body = checked_body(id, "World::apply_force_to_center");
  if (body.type != BodyType::Dynamic) return;
  body.force += force;
  body.awake = true;
}

void World::apply_torque(BodyId id, float torque) {
  require_finite(torque, "World::apply_torque", "torque");
  Body& body = checked_body(id, "World::apply_torque");
  if (body.type != BodyType::Dynamic) return;
  body.torque += torque;
  body.awake = true;
}

void World::apply_linear_impulse(BodyId id, vec2 impulse, vec2 world_point) {
  require_finite(impulse, "World::apply_linear_impulse", "impulse");
  require_finite(world_point, "World::apply_linear_impulse", "world_point");
  Body& body = checked_body(id, "World::apply_linear_impulse");
  if (body.type != BodyType::Dynamic) return;
  body.linear_velocity += impulse * body.inverse_mass;
  body.angular_velocity += effective_inverse_inertia(body, settings_) *
                           cross(world_point - body.transform.position, impulse);
  body.awake = true;
}

void World::apply_angular_impulse(BodyId id, float impulse) {
  require_finite(impulse, "World::apply_angular_impulse", "impulse");
  Body& body = checked_body(id, "World::apply_angular_impulse");
  if (body.type != BodyType::Dynamic) return;
  body.angular_velocity += effective_inverse_inertia(body, settings_) * impulse;
  body.awake = true;
}

void World::set_awake(BodyId id, bool awake) {
  Body& body = checked_body(id, "World::set_awake");
  if (body.type == BodyType::Static) return;
  body.awake = awake;
  body.sleep_time = 0.0f;
  if (!awake) {
    body.linear_velocity = vec2(0.0f);
    body.angular_velocity = 0.0f;
  }
}

bool World::set_contact_enabled(BodyId a, BodyId b, bool enabled) {
  checked_body(a, "World::set_contact_enabled");
  checked_body(b, "World::set_contact_enabled");
  if (b.index < a.index) std::swap(a, b);
  for (std::vector<Contact>* list : {&contacts_, &sleeping_contacts_}) {
    for (Contact& contact : *list) {
      if (contact.body_a == a && contact.body_b == b) {
        contact.enabled = enabled;  // the next step's narrow phase carries it over
        return true;
      }
    }
  }
  return false;
}

// ---- the step ---------------------------------------------------------------------------

void World::step() {
  const Clock::time_point start = Clock::now();
  stats_ = StepStats{};
  diverged_bodies_.clear();
  for (Body& body : bodies_) {
    body.previous_position = body.transform.position;
    body.previous_angle = body.angle;
  }
  if (!solver_ || solver_method_ != settings_.solver) {
    solver_ = make_step_solver(settings_.solver);
    solver_method_ = settings_.solver;
  }
  const Clock::time_point solve_start = Clock::now();
  solver_->step(*this, resolve_solver_context(settings_));
  // Whatever the stages did not time themselves is the solver's own work.
  stats_.solver_ms = elapsed_ms(solve_start) - stats_.broad_phase_ms - stats_.narrow_phase_ms -
                     stats_.integrate_ms - stats_.position_ms;
  if (settings_.enable_sleeping) {
    sleep_islands_.update(bodies_, alive_, contacts_, settings_, settings_.time_step);
  }
  finish_bodies();
  time_ += static_cast<double>(settings_.time_step);
  ++step_count_;
  stats_.body_count = living_body_count_;
  stats_.total_ms = elapsed_ms(start);
}

// One walk over the bodies after the solve: forces cleared, diverged bodies put back where the
// step began (and reported), bounds refreshed and covered by the broad phase (queries search
// its trees; the next step's contacts start from these bounds), awake bodies counted.
void World::finish_bodies() {
  for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
    Body& body = bodies_[i];
    body.force = vec2(0.0f);
    body.torque = 0.0f;
    if (!alive_[i]) continue;
    const bool finite = is_finite(body.transform.position) && std::isfinite(body.angle) &&
                        is_finite(body.linear_velocity) && std::isfinite(body.angular_velocity);
    if (!finite) {
      body.transform = Transform{body.previous_position, Rotation::from_angle(body.previous_angle)};
      body.angle = body.previous_angle;
      body.linear_velocity = vec2(0.0f);
      body.angular_velocity = 0.0f;
      body.awake = false;
      diverged_bodies_.push_back(body.id);
    }
    body.aabb = compute_aabb(body.shape, body.transform);
    broad_phase_.cover(i, body.aabb);
    if (body.awake && body.type != BodyType::Static) ++stats_.awake_body_count;
  }
  bounds_current_ = true;
}

namespace {

bool is_moving(const Body& body) { return body.type != BodyType::Static && body.awake; }

bool pair_less(const Contact& a, const Contact& b) {
  return a.body_a.index < b.body_a.index ||
         (a.body_a.index == b.body_a.index && a.body_b.index < b.body_b.index);
}

// Moves the contacts of `from` that `leaves` selects into `into`, both lists staying in pair
// order (a merge through `scratch`); the others stay in `from`, in order.
template <class Leaves>
void move_contacts(std::vector<Contact>& from, std::vector<Contact>& into,
                   std::vector<Contact>& scratch, Leaves leaves) {
  scratch.clear();
  std::size_t stayed = 0;
  std::size_t merged = 0;
  for (std::size_t i = 0; i < from.size(); ++i) {
    if (!leaves(from[i])) {
      if (stayed != i) from[stayed] = from[i];
      ++stayed;
      continue;
    }
    while (merged < into.size() && pair_less(into[merged], from[i])) scratch.push_back(into[merged++]);
    scratch.push_back(from[i]);
  }
  if (stayed == from.size()) return;
  scratch.insert(scratch.end(), into.begin() + static_cast<std::ptrdiff_t>(merged), into.end());
  std::swap(into, scratch);
  from.erase(from.begin() + static_cast<std::ptrdiff_t>(stayed), from.end());
}

}  // namespace

// Last step's contacts whose bodies no longer move would be dropped by the narrow phase (no
// broad-phase pair has them); they are set aside instead, impulses and all, in pair order.
// Set-aside contacts of pairs that move again go back among last step's contacts, so the
// narrow phase carries their impulses over (warm start) as if they had never slept.
void World::set_aside_sleeping_contacts() {
  // A contact rests only when both its bodies do, so with no body asleep (and none set aside)
  // there is nothing to move: skip the two walks over the contacts.
  bool any_asleep = false;
  for (std::size_t i = 0; i < bodies_.size() && !any_asleep; ++i) {
    any_asleep = alive_[i] && bodies_[i].type != BodyType::Static && !bodies_[i].awake;
  }
  if (!any_asleep && sleeping_contacts_.empty()) return;
  // The scratch and set-aside lists hold no more contacts than the step list has room for;
  // grown with it during warm-up, the first bodies to fall asleep later allocate nothing.
  const std::size_t capacity = contacts_.capacity();
  if (merged_contacts_.capacity() < capacity) merged_contacts_.reserve(capacity);
  if (sleeping_contacts_.capacity() < capacity) sleeping_contacts_.reserve(capacity);
  auto resting = [this](const Contact& contact) {
    return !is_moving(bodies_[contact.body_a.index]) && !is_moving(bodies_[contact.body_b.index]);
  };
  move_contacts(sleeping_contacts_, contacts_, merged_contacts_,
                [&resting](const Contact& contact) { return !resting(contact); });
  move_contacts(contacts_, sleeping_contacts_, merged_contacts_, resting);
}

void World::find_contacts(float dt, ContactVisitor* visitor) {
  Clock::time_point stage = Clock::now();
  set_aside_sleeping_contacts();
  // Bounds are current after a step, `create_body` and `set_transform`; from here to the end
  // of the step the stages move bodies, so they count as stale (a sub-step's next call
  // remakes them).
  if (!bounds_current_) update_bounds(bodies_, alive_);
  bounds_current_ = false;
  compute_speculative_reach(bodies_, alive_, settings_, dt, speculative_reach_);
  compute_speculative_bounds(bodies_, alive_, speculative_reach_, settings_.speculative_margin,
                             speculative_bounds_);
  broad_phase_.find_pairs(bodies_, alive_, speculative_bounds_, settings_.broad_phase, pairs_);
  stats_.broad_phase_ms += elapsed_ms(stage);

  stage = Clock::now();
  stats_.contact_point_count = update_contacts(bodies_, pairs_, speculative_reach_, settings_, dt,
                                               contact_filter_, contacts_, spilled_contacts_,
                                               visitor);
  stats_.pairs_tested = static_cast<int>(pairs_.size());
  stats_.contact_count = static_cast<int>(contacts_.size());
  stats_.sleeping_contact_count = static_cast<int>(sleeping_contacts_.size());
  stats_.narrow_phase_ms += elapsed_ms(stage);
}

void World::integrate_velocities(float dt) {
  const Clock::time_point stage = Clock::now();
  impulse2d::integrate_velocities(bodies_, alive_, settings_, dt);
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::integrate_positions(float dt) {
  const Clock::time_point stage = Clock::now();
  impulse2d::integrate_positions(bodies_, alive_, settings_, dt);
  if (settings_.enable_continuous) {
    stats_.bullets_moved_back += bullet_sweeper_.sweep(bodies_, alive_, settings_, dt, broad_phase_);  // no tunnelling
  }
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::begin_solver_bodies() {
  const Clock::time_point stage = Clock::now();
  solver_body_states_.begin_step(bodies_, alive_, settings_);
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::integrate_solver_velocities(float dt) {
  const Clock::time_point stage = Clock::now();
  solver_body_states_.integrate_velocities(dt);
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::integrate_solver_positions(float dt) {
  const Clock::time_point stage = Clock::now();
  solver_body_states_.integrate_positions(dt);
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::sweep_bullets(float dt) {
  if (!settings_.enable_continuous) return;
  const Clock::time_point stage = Clock::now();
  stats_.bullets_moved_back += bullet_sweeper_.sweep(bodies_, alive_, settings_, dt, broad_phase_);
  stats_.integrate_ms += elapsed_ms(stage);
}

void World::correct_positions() {
  const Clock::time_point stage = Clock::now();
  switch (settings_.position_correction) {
    case PositionCorrection::None: break;
    case PositionCorrection::LinearProjection:
      correct_positions_linear(contacts_, bodies_, settings_);
      break;
    case PositionCorrection::NonlinearGaussSeidel:
      correct_positions_nonlinear(contacts_, bodies_, settings_);
      break;
  }
  stats_.position_ms += elapsed_ms(stage);
}


int World::advance(float frame_time) {
  require_finite(frame_time, "World::advance", "frame_time");
  if (frame_time < 0.0f) throw Error("World::advance: frame_time must be >= 0");
  constexpr float max_frame_time = 0.25f;  // seconds; guards against the spiral of death
  accumulator_ += std::min(frame_time, max_frame_time);
  int steps = 0;
  while (accumulator_ >= settings_.time_step) {
    step();
    accumulator_ -= settings_.time_step;
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
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!alive_[i]) continue;
    const Body& body = bodies_[i];
    const std::uint32_t index = static_cast<std::uint32_t>(i);
    const float values[6] = {body.transform.position.x, body.transform.position.y, body.angle,
                             body.linear_velocity.x,    body.linear_velocity.y,    body.angular_velocity};
    mix_bytes(&index, sizeof index);
    mix_bytes(values, sizeof values);
  }
  return hash;
}

}  // namespace impulse2d
