/// @file golden_run.cpp
#include "golden/scenes/golden_run.h"

#include <algorithm>
#include <map>
#include <string>

#include "scene/scene_loader.h"
#include "demos/scene_registry.h"
#include "scene/trace_writer.h"
#include "golden/error.h"

namespace impulse2d::golden {

namespace {

std::string body_name(BodyId id) {
  std::string name = "body " + std::to_string(id.index);
  if (id.generation != 1) name += " (generation " + std::to_string(id.generation) + ")";
  return name;
}

}  // namespace

GoldenRun::GoldenRun(const GoldenSpec& spec, const SceneVariant& variant) {
  if (!spec.scene_file.empty()) {
    scene_ = std::make_unique<demos::Scene>(demos::load_scene_file(spec.scene_file));
  } else {
    const demos::Scene* builtin = demos::find_builtin_scene(spec.scene);
    if (builtin == nullptr)
      throw GoldenError("golden '" + spec.id() + "': no built-in scene '" + spec.scene + "'");
    scene_ = std::make_unique<demos::Scene>(*builtin);
  }
  if (variant) variant(*scene_);
  scene_->settings.worker_count = spec.worker_count;
  demos::Params params(scene_->params);
  for (const auto& [name, value] : spec.params) params.set(name, value);
  run_ = std::make_unique<demos::SceneRun>(*scene_, params);
  next_script_index_ = std::max(run_->bodies_in_run(), 0);
  track_new_bodies();
}

void GoldenRun::step() {
  run_->step();
  track_new_bodies();
}

void GoldenRun::track_new_bodies() {
  struct Fresh {
    BodyId id;
    vec2 position;
  };
  std::vector<Fresh> fresh;
  const World& world = run_->world();
  for (const BodyId id : world.body_ids()) {
    if (id.index >= creation_by_slot_.size()) creation_by_slot_.resize(id.index + 1, {0u, -1});
    const auto& [generation, index] = creation_by_slot_[id.index];
    if (index >= 0 && generation == id.generation) continue;
    fresh.push_back({id, world.body(id).transform.position});
  }
  if (fresh.empty()) return;
  // The scene run's own creation indices: the scene's bodies, then its spawn events'.
  std::map<std::uint32_t, int> scene_index_by_slot;
  for (int index = 0; index < run_->bodies_in_run(); ++index) {
    if (const auto slot = run_->slot_of(index)) scene_index_by_slot[*slot] = index;
  }
  std::vector<Fresh> scripted;
  for (const Fresh& body : fresh) {
    const auto known = scene_index_by_slot.find(body.id.index);
    if (known != scene_index_by_slot.end()) {
      creation_by_slot_[body.id.index] = {body.id.generation, known->second};
    } else {
      scripted.push_back(body);
    }
  }
  // A script's bodies of one step: by where they are, never by the slot they got.
  std::stable_sort(scripted.begin(), scripted.end(), [](const Fresh& a, const Fresh& b) {
    if (a.position.x != b.position.x) return a.position.x < b.position.x;
    return a.position.y < b.position.y;
  });
  for (const Fresh& body : scripted) {
    creation_by_slot_[body.id.index] = {body.id.generation, next_script_index_++};
  }
}

std::vector<BodyPose> GoldenRun::body_poses() const {
  std::vector<BodyPose> poses;
  const World& world = run_->world();
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    const int index = id.index < creation_by_slot_.size() ? creation_by_slot_[id.index].second : -1;
    const auto named = scene_->body_names.find(index);
    const std::string name = named != scene_->body_names.end()
                                 ? named->second + " (#" + std::to_string(index) + ")"
                                 : "body #" + std::to_string(index);
    poses.push_back(
        BodyPose{name, body.transform.position.x, body.transform.position.y, body.angle});
  }
  return poses;
}

std::vector<BodyPose> body_poses(const World& world) {
  std::vector<BodyPose> poses;
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    poses.push_back(
        BodyPose{body_name(id), body.transform.position.x, body.transform.position.y, body.angle});
  }
  return poses;
}

PhysicsSample sample_physics(const World& world) {
  PhysicsSample sample;
  sample.step = world.step_count();
  sample.energy = demos::mechanical_energy(world);
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    if (body.type != BodyType::Dynamic) continue;
    const double mass = body.mass;
    const double px = mass * body.linear_velocity.x;
    const double py = mass * body.linear_velocity.y;
    sample.momentum_x += px;
    sample.momentum_y += py;
    sample.angular_momentum += body.transform.position.x * py - body.transform.position.y * px +
                               static_cast<double>(body.inertia) * body.angular_velocity;
  }
  sample.contacts = static_cast<int>(world.contacts().size());
  sample.bodies = static_cast<int>(world.body_ids().size());
  return sample;
}

}  // namespace impulse2d::golden
