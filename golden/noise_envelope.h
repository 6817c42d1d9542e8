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
  /// Living bodies (spawns and removals change it); -1 when not recorded (sidecars before
  /// issue 29).
  int bodies = -1;
};

/// One checkpoint of the envelope: the golden run's quantities and how far the perturbed
/// runs strayed from them (each field of `spread` is the largest |perturbed - golden| at
/// this checkpoint or an earlier one: noise, once there, persists in some quantity).
struct NoiseCheckpoint {
  PhysicsSample golden;  ///< the golden run at this step
  PhysicsSample spread;  ///< the noise of each quantity (its `step` equals golden.step)
  /// The largest distance any body of any perturbed run strayed from the golden run, at
  /// this checkpoint or before, metres: how far the scene has amplified rounding by this
  /// step. -1 when not recorded (sidecars before issue 29).
  double body_spread = -1.0;
};

/// How far one body strayed under the perturbations, over every step up to the frame.
struct BodyNoise {
  std::string name;       ///< the body's label, as in `BodyPose::name`
  double distance = 0.0;  ///< largest centre-of-mass distance from the golden run, metres
  double rotation = 0.0;  ///< largest angle difference from the golden run, radians
  /// True when some perturbed run had already removed this body by the frame (the golden
  /// run still has it): its absence in a later run is noise too.
  bool may_be_missing = false;
};

/// Everything measured about a golden's sensitivity to rounding.
struct NoiseEnvelope {
  /// What was perturbed, one run each, e.g. "time_step +1 ulp".
  std::vector<std::string> perturbations;
  /// Quantities at the checkpoint steps (`noise_checkpoint_steps`), ascending by step.
  std::vector<NoiseCheckpoint> checkpoints;
  /// Per body, in the golden's body order.
  std::vector<BodyNoise> bodies;
  /// Bodies some perturbed run had alive at the frame that the golden run had not (removed
  /// earlier, or spawned only there): their presence in a later run is noise too.
  std::vector<std::string> extra_bodies;

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

/// "Numerical noise" is said only where the envelope is small against the scene: where no
/// body moved, and the envelope lets no body move, more than this fraction of the scene's
/// size (the diagonal of the box around the golden's bodies at the frame, at least 1 m).
/// Beyond it a rounding change *could* explain the change, but so could a real one: the
/// verdict is "cannot tell", never the advice to promote.
inline constexpr double kNoiseBoundFraction = 0.01;

/// One way a run left the envelope.
struct EnvelopeEscape {
  std::string what;      ///< e.g. "body 12 position" or "angular momentum at step 75"
  double measured = 0.0;  ///< |actual - golden|
  double envelope = 0.0;  ///< the noise the perturbed runs showed
  std::string unit;      ///< "m", "rad", "J", ...; empty for counts
  bool body = false;     ///< true for a body's pose, false for a whole-world quantity
  /// True when the body or sample exists on one side only (nothing to measure then).
  bool unmatched = false;
  /// The golden run's value (0 for a body's position or angle): sets the floor under the
  /// envelope when the escape is ordered by size (`severity`).
  double reference = 0.0;

  /// How far outside its envelope: measured / max(envelope, 1e-6 x (1 + |reference|)), so
  /// an escape from a zero envelope by rounding-sized amounts (4e-11 of a momentum) ranks
  /// below a large escape from a real envelope; infinite for an unmatched body or sample.
  double severity() const;

  /// "body 12 position off by 0.31 m (noise envelope 0.002 m, limit 0.004)"; for an
  /// unmatched one just `what`.
  std::string describe() const;
};

/// The judgement of one run against a golden's envelope.
struct NoiseVerdict {
  /// Every escape, worst first (by `EnvelopeEscape::severity`: size relative to its
  /// envelope, unmatched bodies first); empty when the run stayed inside the envelope.
  std::vector<EnvelopeEscape> escapes;
  /// How many quantities were compared (bodies x 2 + checkpoints x 5).
  std::size_t compared = 0;
  /// The scene's size: the diagonal of the box around the golden's bodies at the frame
  /// (at least 1 m), metres.
  double scene_scale = 1.0;
  /// The noise bound: `kNoiseBoundFraction` x `scene_scale`, metres.
  double bound = 0.01;
  /// The farthest any body of this run is from the golden run at the frame, metres, and its
  /// name.
  double largest_move = 0.0;
  std::string largest_move_body;
  /// The farthest the envelope lets a body move at the frame (`kNoiseMargin` x the largest
  /// body noise), metres.
  double envelope_reach = 0.0;
  /// The first checkpoint step at which the perturbed runs already differ by more than
  /// `bound` (from then on the scene amplifies rounding beyond what can be told from a
  /// change); -1 when they never do, or the sidecar does not record it.
  std::int64_t stops_telling_step = -1;
  /// The last checkpoint step before `stops_telling_step` (a frame there still tells noise
  /// from a change); -1 when none does.
  std::int64_t last_telling_step = -1;
  /// True when the sidecar records the per-step spread (`NoiseCheckpoint::body_spread`).
  bool spread_recorded = false;
  /// Bodies alive on one side only ("body #43 (alive in this run only)") in a scene whose
  /// perturbed runs already disagree on which bodies are alive at the frame (some body
  /// `may_be_missing`, or `extra_bodies`): eight samples cannot say which bodies rounding
  /// may swap, so these are not escapes but make the verdict "cannot tell".
  std::vector<std::string> unsampled_living_set;

  /// True when nothing left the envelope.
  bool within() const { return escapes.empty(); }
  /// True when the run stayed inside the envelope but the envelope (or the run's largest
  /// move) is beyond `bound`: the scene's own chaos could explain it, and so could a real
  /// change.
  bool cannot_tell() const {
    return within() &&
           (largest_move > bound || envelope_reach > bound || !unsampled_living_set.empty());
  }
  /// "the perturbed runs ... step N ... frame M" for a cannot-tell verdict.
  std::string describe_cannot_tell() const;
  /// The `count` worst escapes, one per part ("1. ball (#3) position off by ...", joined by
  /// `separator`), then "(N more outside the envelope: B bodies, Q quantities)" when there
  /// are more; or "every body and quantity inside the noise envelope (N compared)".
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
