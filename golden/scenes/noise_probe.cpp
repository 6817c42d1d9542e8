/// @file noise_probe.cpp
#include "golden/scenes/noise_probe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include "core/world.h"

namespace impulse2d::golden {

namespace {

/// The largest rounding difference the envelope covers, in ulps: a reordered sum of a few
/// terms, another compiler's or library's rounding of an expression, differ from the
/// original by a few ulps, and up to the point where a chaotic scene saturates, divergence
/// grows in proportion to the difference it started from.
constexpr int kRoundingUlps = 16;

/// The time step perturbations, in ulps.
constexpr int kPerturbationUlps[] = {1, -1, kRoundingUlps, -kRoundingUlps};

/// One perturbation: its name and the change it makes to a scene copy.
struct Perturbation {
  std::string name;
  SceneVariant change;
};

/// `value` moved by `ulps` units in the last place (up when positive, down when negative).
float move_ulps(float value, int ulps) {
  const float direction = ulps > 0 ? std::numeric_limits<float>::infinity()
                                   : -std::numeric_limits<float>::infinity();
  for (int i = 0; i < std::abs(ulps); ++i) value = std::nextafter(value, direction);
  return value;
}

/// " +1 ulp", " -16 ulps".
std::string ulps_text(int ulps) {
  return std::string(" ") + (ulps > 0 ? "+" : "-") + std::to_string(std::abs(ulps)) +
         (std::abs(ulps) == 1 ? " ulp" : " ulps");
}

/// Moves every dynamic body the scene builds by `ulps` of its x and of its y, right after
/// `build`: rounding of any body's initial position.
SceneVariant nudge_dynamic_bodies(int ulps) {
  return [ulps](demos::Scene& scene) {
    scene.build = [build = scene.build, ulps](World& world, const demos::Params& params) {
      build(world, params);
      for (const BodyId id : world.body_ids()) {
        const BodyView body = world.body(id);
        if (body.type != BodyType::Dynamic) continue;
        world.set_transform(id,
                            vec2(move_ulps(body.transform.position.x, ulps),
                                 move_ulps(body.transform.position.y, ulps)),
                            body.angle);
      }
    };
  };
}

std::vector<Perturbation> perturbations() {
  std::vector<Perturbation> list;
  for (const int ulps : kPerturbationUlps) {
    list.push_back({"time_step" + ulps_text(ulps), [ulps](demos::Scene& scene) {
                      scene.settings.time_step = move_ulps(scene.settings.time_step, ulps);
                    }});
  }
  for (const int ulps : {1, -kRoundingUlps}) {
    list.push_back({"gravity y" + ulps_text(ulps), [ulps](demos::Scene& scene) {
                      scene.settings.gravity.y = move_ulps(scene.settings.gravity.y, ulps);
                    }});
    list.push_back({"dynamic bodies' x and y" + ulps_text(ulps), nudge_dynamic_bodies(ulps)});
  }
  return list;
}

/// `second` after `first`, so a perturbation applies on top of the caller's variant.
SceneVariant chain(const SceneVariant& first, const SceneVariant& second) {
  return [first, second](demos::Scene& scene) {
    if (first) first(scene);
    second(scene);
  };
}

/// Spread of each quantity: the largest |perturbed - golden|.
void widen(PhysicsSample& spread, const PhysicsSample& golden, const PhysicsSample& perturbed) {
  spread.energy = std::max(spread.energy, std::abs(perturbed.energy - golden.energy));
  spread.momentum_x = std::max(spread.momentum_x, std::abs(perturbed.momentum_x - golden.momentum_x));
  spread.momentum_y = std::max(spread.momentum_y, std::abs(perturbed.momentum_y - golden.momentum_y));
  spread.angular_momentum = std::max(
      spread.angular_momentum, std::abs(perturbed.angular_momentum - golden.angular_momentum));
  spread.contacts = std::max(spread.contacts, std::abs(perturbed.contacts - golden.contacts));
  spread.bodies = std::max(spread.bodies, std::abs(perturbed.bodies - golden.bodies));
}

}  // namespace

NoiseEnvelope measure_noise_envelope(const GoldenSpec& spec, const SceneVariant& variant) {
  GoldenRun golden(spec, variant);
  std::vector<std::unique_ptr<GoldenRun>> perturbed;
  NoiseEnvelope envelope;
  for (const Perturbation& perturbation : perturbations()) {
    perturbed.push_back(std::make_unique<GoldenRun>(spec, chain(variant, perturbation.change)));
    envelope.perturbations.push_back(perturbation.name);
  }

  // Bodies by creation order (`GoldenRun::body_poses`), never by slot: a perturbed run that
  // removes a body a step earlier, or spawns into another slot, still names its bodies alike.
  std::map<std::string, BodyNoise> noise;
  double body_spread = 0.0;  // the largest distance of any body so far
  auto record_bodies = [&] {
    const std::vector<BodyPose> reference = golden.body_poses();
    for (const auto& run : perturbed) {
      std::map<std::string, const BodyPose*> by_name;
      const std::vector<BodyPose> poses = run->body_poses();
      for (const BodyPose& pose : poses) by_name[pose.name] = &pose;
      for (const BodyPose& pose : reference) {
        const auto found = by_name.find(pose.name);
        if (found == by_name.end()) continue;  // not (yet, or any more) in that run
        BodyNoise& body = noise[pose.name];
        const double distance = std::hypot(found->second->x - pose.x, found->second->y - pose.y);
        body.distance = std::max(body.distance, distance);
        body.rotation = std::max(body.rotation, std::abs(found->second->angle - pose.angle));
        body_spread = std::max(body_spread, distance);
      }
    }
  };

  const std::vector<std::int64_t> checkpoints = noise_checkpoint_steps(spec.step);
  std::size_t next_checkpoint = 0;
  record_bodies();
  while (golden.run().step_count() < spec.step) {
    golden.step();
    for (const auto& run : perturbed) run->step();
    record_bodies();
    if (next_checkpoint < checkpoints.size() &&
        golden.run().step_count() == checkpoints[next_checkpoint]) {
      NoiseCheckpoint checkpoint;
      checkpoint.golden = sample_physics(golden.world());
      checkpoint.spread.step = checkpoint.golden.step;
      // Noise, once there, does not go away: a divergence that shows in a quantity now may
      // show in another later (two runs coming to rest at different places have the same
      // momentum again), so each spread is the largest up to this step.
      if (!envelope.checkpoints.empty()) checkpoint.spread = envelope.checkpoints.back().spread;
      checkpoint.spread.step = checkpoint.golden.step;
      checkpoint.spread.bodies = std::max(checkpoint.spread.bodies, 0);
      for (const auto& run : perturbed) {
        widen(checkpoint.spread, checkpoint.golden, sample_physics(run->world()));
      }
      checkpoint.body_spread = body_spread;
      envelope.checkpoints.push_back(checkpoint);
      ++next_checkpoint;
    }
  }
  // Only the bodies alive at the frame are judged; which bodies are alive is noise too (a
  // body some perturbed run had removed by now, or had and the golden run had not).
  const std::vector<BodyPose> reference = golden.body_poses();
  std::set<std::string> alive;
  for (const BodyPose& pose : reference) alive.insert(pose.name);
  std::set<std::string> missing_somewhere;
  std::set<std::string> extra;
  for (const auto& run : perturbed) {
    std::set<std::string> names;
    for (const BodyPose& pose : run->body_poses()) {
      names.insert(pose.name);
      if (alive.count(pose.name) == 0) extra.insert(pose.name);
    }
    for (const std::string& name : alive) {
      if (names.count(name) == 0) missing_somewhere.insert(name);
    }
  }
  for (const BodyPose& pose : reference) {
    const BodyNoise& body = noise[pose.name];
    envelope.bodies.push_back(
        {pose.name, body.distance, body.rotation, missing_somewhere.count(pose.name) != 0});
  }
  envelope.extra_bodies.assign(extra.begin(), extra.end());
  return envelope;
}

NoiseMeasurer scene_noise_measurer(const GoldenSpec& spec, const SceneVariant& variant) {
  return [spec, variant] { return measure_noise_envelope(spec, variant); };
}

}  // namespace impulse2d::golden
