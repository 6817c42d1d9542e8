#pragma once
/// @file noise_envelope.h
/// How far a scene's own rounding noise carries it, measured when a golden is made, and the
/// judgement of a later run against it: a divergence inside the envelope is *numerical
/// noise* (a chaotic scene amplified a rounding change), one beyond it is *behaviour
/// changed*, naming the bodies and quantities that left the envelope.
///
/// The envelope is measured by rerunning the golden's scene with perturbations of 1 and 16 ulps
/// (golden/scenes/noise_probe.h); this file holds the data and the pure judgement,
/// no physics.

#include "golden/body_drift.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// Whole-world physical quantities at one step: what a refactor must keep even where
/// single trajectories diverge.
struct PhysicsSample {
  std::int64_t step = 0;          ///< steps taken when sampled
  double energy = 0.0;            ///< kinetic + rotational + gravitational potential (y = 0), J
  double momentum_x = 0.0;        ///< total linear momentum, x, kg m/s
  double momentum_y = 0.0;        ///< total linear momentum, y, kg m/s
  double angular_momentum = 0.0;  ///< about the world origin, kg m^2/s
  int contacts = 0;               ///< touching pairs
};

/// One checkpoint of the envelope: the golden run's quantities and how far the perturbed
/// runs strayed from them (each field of `spread` is the largest |perturbed - golden| at
/// this checkpoint or an earlier one: noise, once there, persists in some quantity).
struct NoiseCheckpoint {
  PhysicsSample golden;  ///< the golden run at this step
  PhysicsSample spread;  ///< the noise of each quantity (its `step` equals golden.step)
};

/// How far one body strayed under the perturbations, over every step up to the frame.
struct BodyNoise {
  std::string name;       ///< the body's label, as in `BodyPose::name`
  double distance = 0.0;  ///< largest centre-of-mass distance from the golden run, metres
  double rotation = 0.0;  ///< largest angle difference from the golden run, radians
};

/// Everything measured about a golden's sensitivity to rounding.
struct NoiseEnvelope {
  /// What was perturbed, one run each, e.g. "time_step +1 ulp".
  std::vector<std::string> perturbations;
  /// Quantities at the checkpoint steps (`noise_checkpoint_steps`), ascending by step.
  std::vector<NoiseCheckpoint> checkpoints;
  /// Per body, in the golden's body order.
  std::vector<BodyNoise> bodies;

  /// True when nothing was measured (a sidecar without an envelope).
  bool empty() const { return perturbations.empty(); }
};

/// The steps at which quantities are sampled for a golden at `frame`: `count` steps spread
/// evenly over 1..frame, ending at `frame` (fewer when frame < count; none for frame 0).
std::vector<std::int64_t> noise_checkpoint_steps(std::int64_t frame, int count = 32);

/// A quantity counts as noise while it stays within this multiple of its envelope. The
/// envelope is the largest of a few perturbed runs; where a chaotic scene has saturated
/// (trajectories fully decorrelated) another rounding change is one more draw from the same
/// spread and lands beyond the largest of eight draws one time in nine, but rarely beyond
/// twice it. A physics change leaves the envelope by orders of magnitude at the first
/// checkpoints, before the scene saturates.
inline constexpr double kNoiseMargin = 2.0;

/// One way a run left the envelope.
struct EnvelopeEscape {
  std::string what;      ///< e.g. "body 12 position" or "angular momentum at step 75"
  double measured = 0.0;  ///< |actual - golden|
  double envelope = 0.0;  ///< the noise the perturbed runs showed
  std::string unit;      ///< "m", "rad", "J", ...; empty for counts
  bool body = false;     ///< true for a body's pose, false for a whole-world quantity
  /// True when the body or sample exists on one side only (nothing to measure then).
  bool unmatched = false;

  /// "body 12 position off by 0.31 m (noise envelope 0.002 m, limit 0.004)"; for an
  /// unmatched one just `what`.
  std::string describe() const;
};

/// The judgement of one run against a golden's envelope.
struct NoiseVerdict {
  /// Every escape, worst first (by measured / envelope, an escape from a zero envelope
  /// first of all); empty when the run stayed inside the envelope.
  std::vector<EnvelopeEscape> escapes;
  /// How many quantities were compared (bodies x 2 + checkpoints x 5).
  std::size_t compared = 0;

  /// True when nothing left the envelope.
  bool within() const { return escapes.empty(); }
  /// "quantities: <the `count` worst whole-world escapes><separator>bodies: <the `count`
  /// worst body escapes> (B bodies outside)", each part only when it has escapes; or "every
  /// body and quantity inside the noise envelope (N compared)".
  std::string describe(std::size_t count, const std::string& separator = "; ") const;
};

/// Compares a run with the golden run: each body's pose at the frame (matched by name)
/// against that body's noise, and each quantity sampled at a checkpoint step of the
/// envelope against that checkpoint's spread, each allowed `kNoiseMargin` times its noise. A body or sample the other side lacks is an
/// escape too (the scene's make-up changed).
NoiseVerdict judge_against_envelope(const NoiseEnvelope& envelope,
                                    const std::vector<BodyPose>& golden_bodies,
                                    const std::vector<BodyPose>& actual_bodies,
                                    const std::vector<PhysicsSample>& actual_samples);

/// The envelope as JSON: {"perturbations": [...], "checkpoints": [{"step", "energy",
/// "energy_noise", ...}], "bodies": [{"name", "distance", "rotation"}]}.
nlohmann::json noise_envelope_to_json(const NoiseEnvelope& envelope);

/// Validates and converts `noise_envelope_to_json`'s form. Throws `GoldenError` naming
/// `origin` and the field for missing, unknown, mistyped, negative or non-finite values and
/// checkpoints out of step order.
NoiseEnvelope noise_envelope_from_json(const nlohmann::json& object, const std::string& origin);

}  // namespace impulse2d::golden
