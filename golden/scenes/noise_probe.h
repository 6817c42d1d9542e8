#pragma once
/// @file noise_probe.h
/// Measures a golden's noise envelope: the scene run as the golden runs it and, side by
/// side, runs with its inputs perturbed by 1 and 16 ulps; how far each perturbed run strays
/// from the unperturbed one, per body over every step up to the golden's frame and per
/// whole-world quantity at the checkpoint steps, is what rounding alone can do to the scene.

#include "golden/check_run.h"
#include "golden/noise_envelope.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/golden_run.h"

namespace impulse2d::golden {

/// The envelope of `spec` (with `variant` applied to every run) under eight perturbations
/// of a float input by 1 and by 16 units in the last place (the size of the rounding
/// differences a reordered sum or another compiler makes): the time step by +-1 and +-16
/// ulps, gravity's y, and the position (x and y) of every dynamic body the scene builds, by
/// +1 and -16 ulps.
NoiseEnvelope measure_noise_envelope(const GoldenSpec& spec, const SceneVariant& variant = nullptr);

/// A `NoiseMeasurer` of `measure_noise_envelope`.
NoiseMeasurer scene_noise_measurer(const GoldenSpec& spec, const SceneVariant& variant = nullptr);

}  // namespace impulse2d::golden
