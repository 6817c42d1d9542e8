/// @file scene_run.cpp
#include "scene/scene_run.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "scene/interrupt.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

WorldSettings settings_with_model(const Scene& scene) {
  WorldSettings settings = scene.settings;
  apply_model(scene.model, settings);
  return settings;
}

}  // namespace

SceneRun::SceneRun(const Scene& scene, const Params& params)
    : scene_(scene), params_(params), world_(settings_with_model(scene)) {
  if (scene.build) scene.build(world_, params_);
  verify_model();
  if (scene.script) script_ = scene.script(params_);

  for (const SceneEvent& event : scene.events) events_.push_back(&event);
  std::stable_sort(events_.begin(), events_.end(),
                   [](const SceneEvent* a, const SceneEvent* b) { return a->step < b->step; });

  created_ = world_.body_ids();
  const std::vector<std::string> buttons =
      script_ ? script_->buttons() : std::vector<std::string>{};
  int bodies_so_far = static_cast<int>(created_.size());
  for (const SceneEvent* event : events_) {
    const bool pushes = event->kind == SceneEventKind::Impulse || event->kind == SceneEventKind::Force;
    const bool names_body = pushes || event->kind == SceneEventKind::Remove;
    if (names_body && (event->body < 0 || event->body >= bodies_so_far)) {
      throw UsageError(scene.source + ": " + event->origin + ": body " +
                       std::to_string(event->body) + " does not exist at step " +
                       std::to_string(event->step) + " (" + std::to_string(bodies_so_far) +
                       " bodies created by then)");
    }
    // The builder's bodies exist now: one an impulse or a force cannot move is an error before
    // the run (a scene file's are rejected when it loads; a spawned one, when the event applies).
    if (pushes && static_cast<std::size_t>(event->body) < created_.size()) {
      check_movable(*event, world_.body(created_[static_cast<std::size_t>(event->body)]).type);
    }
    if (event->kind == SceneEventKind::Spawn) ++bodies_so_far;
    if (event->kind == SceneEventKind::Button &&
        std::find(buttons.begin(), buttons.end(), event->button) == buttons.end()) {
      std::string known;
      for (const std::string& name : buttons) known += (known.empty() ? "" : ", ") + name;
      throw UsageError(scene.source + ": " + event->origin + ": scene " + scene.name +
                       " has no button '" + event->button +
                       "' (its buttons: " + (known.empty() ? std::string("none") : known) + ")");
    }
  }
  bodies_in_run_ = bodies_so_far;
  for (const JointSpec& spec : scene.joints) create_joint(spec, 0);
}

void SceneRun::create_joint(const JointSpec& spec, std::int64_t step) {
  const auto body = [&](int index) {
    const bool exists = index >= 0 && static_cast<std::size_t>(index) < created_.size() &&
                        world_.is_valid(created_[static_cast<std::size_t>(index)]);
    if (!exists) {
      throw UsageError(scene_.source + ": " + spec.origin + ": body " + std::to_string(index) +
                       " does not exist at step " + std::to_string(step) +
                       " (not created yet, or removed)");
    }
    return created_[static_cast<std::size_t>(index)];
  };
  const BodyId a = body(spec.body_a);
  const BodyId b = body(spec.body_b);
  JointId id;
  try {
    id = create_scene_joint(world_, spec, a, b);
  } catch (const Error& error) {
    throw UsageError(scene_.source + ": " + spec.origin + ": " + error.what());
  }
  if (!spec.name.empty()) joints_[spec.name] = id;
}

JointId SceneRun::event_joint(const SceneEvent& event) const {
  const std::optional<JointId> id = joint_named(event.joint_name);
  if (!id) {
    throw UsageError(scene_.source + ": " + event.origin + ": joint \"" + event.joint_name +
                     "\" does not exist at step " + std::to_string(event.step) +
                     " (not created yet, destroyed, or one of its bodies was removed)");
  }
  return *id;
}

std::optional<JointId> SceneRun::joint_named(const std::string& name) const {
  const auto found = joints_.find(name);
  if (found == joints_.end() || !world_.is_valid(found->second)) return std::nullopt;
  return found->second;
}

void SceneRun::verify_model() const {
  try {
    verify_shape_kinds(scene_.model, world_, scene_.name);
  } catch (const UsageError& error) {
    if (scene_.source == "built-in") throw;
    throw UsageError(scene_.source + ": " + error.what() + " (at step " +
                     std::to_string(world_.step_count()) + ")");
  }
}

BodyId SceneRun::event_body(const SceneEvent& event) const {
  const BodyId id = created_[static_cast<std::size_t>(event.body)];
  if (!world_.is_valid(id)) {
    throw UsageError(scene_.source + ": " + event.origin + ": body " + std::to_string(event.body) +
                     " was already removed before step " + std::to_string(event.step));
  }
  return id;
}

void SceneRun::check_movable(const SceneEvent& event, BodyType type) const {
  if (type == BodyType::Dynamic) return;
  std::string label = "body " + std::to_string(event.body);
  const auto name = scene_.body_names.find(event.body);
  if (name != scene_.body_names.end()) label += " (\"" + name->second + "\")";
  throw UsageError(scene_.source + ": " + event.origin + ": " +
                   unmovable_body_reason(label, type, event.kind));
}

void SceneRun::apply_event(const SceneEvent& event) {
  switch (event.kind) {
    case SceneEventKind::Impulse: {
      const BodyId id = event_body(event);
      check_movable(event, world_.body(id).type);
      const vec2 point = event.point ? *event.point : world_.body(id).transform.position;
      world_.apply_linear_impulse(id, event.impulse, point);
      if (event.angular_impulse != 0.0f) world_.apply_angular_impulse(id, event.angular_impulse);
      break;
    }
    case SceneEventKind::Force: {
      const BodyId id = event_body(event);
      check_movable(event, world_.body(id).type);
      // Where it acts, in the body's frame: it moves with the body for the whole window.
      const Transform& transform = world_.body(id).transform;
      const vec2 local_point =
          event.point ? transform.apply_inverse(*event.point) : vec2(0.0f, 0.0f);
      forces_.push_back(ActiveForce{&event, event.step + event.steps, local_point});
      break;
    }
    case SceneEventKind::Spawn:
      created_.push_back(create_spawn(world_, event.spawn));
      break;
    case SceneEventKind::Remove:
      world_.remove_body(event_body(event));
      break;
    case SceneEventKind::Button:
      script_->button(world_, event.button, event.pressed);
      break;
    case SceneEventKind::CreateJoint:
      create_joint(event.joint, event.step);
      break;
    case SceneEventKind::DestroyJoint:
      world_.destroy_joint(event_joint(event));
      break;
    case SceneEventKind::MouseTarget:
      world_.set_mouse_target(event_joint(event), event.target);
      break;
  }
}

std::vector<std::uint8_t> SceneRun::save_script_state() const {
  return script_ ? script_->save_state() : std::vector<std::uint8_t>{};
}

void SceneRun::restore_snapshot(const std::vector<std::uint8_t>& snapshot,
                                const std::vector<std::uint8_t>& script_state) {
  // A copy keeps the world's contact filter (a script that installs its own installs it again
  // in `restore_state`).
  World restored = world_;
  restored.restore_snapshot(snapshot);  // throws Error, leaving this run as it was
  const std::int64_t step = restored.step_count();
  std::size_t next = 0;
  for (; next < events_.size() && events_[next]->step < step; ++next) {
    const SceneEvent& event = *events_[next];
    const bool done = event.kind == SceneEventKind::Impulse || event.kind == SceneEventKind::Button ||
                      (event.kind == SceneEventKind::Force && event.step + event.steps <= step);
    if (!done) {
      throw UsageError(scene_.source + ": " + event.origin + " (step " +
                       std::to_string(event.step) + ") comes before the saved state's step " +
                       std::to_string(step) +
                       "; only impulses, button presses and finished forces can be resumed from "
                       "a saved state");
    }
  }
  std::unique_ptr<StepScript> script;
  if (scene_.script) {
    if (script_state.empty()) throw Error("the saved state holds no state of the scene's script");
    script = scene_.script(params_);
    script->restore_state(restored, script_state);  // throws Error; this run is untouched
  } else if (!script_state.empty()) {
    throw Error("the saved state holds a script's state, but scene " + scene_.name +
                " has no script");
  }
  world_ = std::move(restored);
  script_ = std::move(script);
  next_event_ = next;
  forces_.clear();
  restored_ = true;
}

void SceneRun::step() {
  const std::int64_t step = world_.step_count();
  bool changed = false;
  while (next_event_ < events_.size() && events_[next_event_]->step == step) {
    apply_event(*events_[next_event_++]);
    changed = true;
  }
  apply_forces(step);
  if (script_) {
    script_->before_step(world_, step);
    changed = true;
  }
  if (changed) verify_model();
  check_interrupt();
  world_.step();
  for (const BodyId id : world_.diverged_bodies()) {
    const auto found = std::find(created_.begin(), created_.end(), id);
    const int index = found == created_.end() ? -1 : static_cast<int>(found - created_.begin());
    const auto name = scene_.body_names.find(index);
    divergences_.push_back(Divergence{world_.step_count(), index,
                                      name == scene_.body_names.end() ? "" : name->second});
    if (strict_) {
      throw std::runtime_error(describe_divergence(scene_, divergences_.back()) +
                               " (--strict makes this an error)");
    }
  }
}

void SceneRun::apply_forces(std::int64_t step) {
  // Forces are cleared after every world step, so each force event's is applied again before
  // each step of its window [step, step + steps); finished ones are dropped.
  forces_.erase(std::remove_if(forces_.begin(), forces_.end(),
                               [step](const ActiveForce& force) { return step >= force.end; }),
                forces_.end());
  for (const ActiveForce& force : forces_) {
    const SceneEvent& event = *force.event;
    const BodyId id = created_[static_cast<std::size_t>(event.body)];
    if (!world_.is_valid(id)) {
      throw UsageError(scene_.source + ": " + event.origin + ": body " +
                       std::to_string(event.body) + " was removed before step " +
                       std::to_string(step) + ", within the force's steps " +
                       std::to_string(event.step) + ".." + std::to_string(force.end - 1));
    }
    const vec2 point = world_.body(id).transform.apply(force.local_point);
    world_.apply_force(id, event.force, point);
    if (event.torque != 0.0f) world_.apply_torque(id, event.torque);
  }
}

std::string describe_divergence(const Scene& scene, const Divergence& divergence) {
  return scene.source + ": body " + std::to_string(divergence.body) +
         (divergence.name.empty() ? "" : " (\"" + divergence.name + "\")") + " of scene " +
         scene.name + " diverged in step " + std::to_string(divergence.step) +
         " (its state became non-finite; the world restored its previous state and stopped it)";
}

std::optional<std::uint32_t> SceneRun::slot_of(int creation_index) const {
  if (creation_index < 0 || static_cast<std::size_t>(creation_index) >= created_.size()) return std::nullopt;
  const BodyId id = created_[static_cast<std::size_t>(creation_index)];
  if (!world_.is_valid(id)) return std::nullopt;
  return id.index;
}

std::function<std::string(std::uint32_t slot)> SceneRun::body_labels() const {
  return [this](std::uint32_t slot) {
    for (const auto& [index, name] : scene_.body_names) {
      const std::optional<std::uint32_t> found = slot_of(index);
      if (found && *found == slot) return name;
    }
    return std::string();
  };
}

std::optional<vec2> SceneRun::followed_position() const {
  const CameraSpec& camera = scene_.view.camera;
  if (camera.mode != CameraSpec::Mode::Follow) return std::nullopt;
  std::optional<BodyId> body = script_ ? script_->followed_body() : std::nullopt;
  if (!body && camera.follow_body >= 0 &&
      static_cast<std::size_t>(camera.follow_body) < created_.size()) {
    body = created_[static_cast<std::size_t>(camera.follow_body)];
  }
  if (!body || !world_.is_valid(*body)) return std::nullopt;
  return world_.body(*body).transform.position;
}

std::function<void(DebugDraw&, const DebugDrawOptions&)> SceneRun::script_overlays() const {
  return [this](DebugDraw& draw, const DebugDrawOptions& options) {
    if (script_ && (options.flags & ~std::uint32_t{draw_shapes}) != 0) {
      script_->draw(world_, draw, options);
    }
  };
}

}  // namespace impulse2d::demos
