/// @file golden_run.cpp
#include "golden/scenes/golden_run.h"

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
  demos::Params params(scene_->params);
  for (const auto& [name, value] : spec.params) params.set(name, value);
  run_ = std::make_unique<demos::SceneRun>(*scene_, params);
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
  return sample;
}

}  // namespace impulse2d::golden
