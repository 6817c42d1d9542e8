/// @file noise_probe.cpp
#include "golden/scenes/noise_probe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
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

  // Bodies by name; a body one run has and another lacks cannot be compared, so it is left
  // to the judgement, which reports it.
  std::map<std::string, BodyNoise> noise;
  auto record_bodies = [&] {
    const std::vector<BodyPose> reference = body_poses(golden.world());
    for (const auto& run : perturbed) {
      const std::vector<BodyPose> poses = body_poses(run->world());
      for (std::size_t i = 0; i < reference.size() && i < poses.size(); ++i) {
        if (poses[i].name != reference[i].name) continue;
        BodyNoise& body = noise[reference[i].name];
        body.distance = std::max(
            body.distance, std::hypot(poses[i].x - reference[i].x, poses[i].y - reference[i].y));
        body.rotation = std::max(body.rotation, std::abs(poses[i].angle - reference[i].angle));
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
      for (const auto& run : perturbed) {
        widen(checkpoint.spread, checkpoint.golden, sample_physics(run->world()));
      }
      envelope.checkpoints.push_back(checkpoint);
      ++next_checkpoint;
    }
  }
  // Only the bodies alive at the frame are judged.
  for (const BodyPose& pose : body_poses(golden.world())) {
    const BodyNoise& body = noise[pose.name];
    envelope.bodies.push_back({pose.name, body.distance, body.rotation});
  }
  return envelope;
}

NoiseMeasurer scene_noise_measurer(const GoldenSpec& spec, const SceneVariant& variant) {
  return [spec, variant] { return measure_noise_envelope(spec, variant); };
}

}  // namespace impulse2d::golden
