#pragma once
/// @file timeline_strip.h
/// A timeline of the whole run drawn as a strip under a frame: energy, contact count and the
/// deepest penetration over the steps, each scaled to its own range, with the current step
/// marked.

#include "render/palette.h"

#include <cstdint>
#include <vector>

namespace impulse2d::render {

class PrimitiveRenderer;

/// The run's figures at one step.
struct TimelineSample {
  std::int64_t step = 0;          ///< steps taken
  double energy = 0.0;            ///< total mechanical energy, J
  int contacts = 0;               ///< touching pairs
  float max_penetration = 0.0f;   ///< deepest overlap of any contact point, m (0 when none)
};

/// Colour of the energy curve.
constexpr Color timeline_energy_color{0.84f, 0.37f, 0.00f, 1.0f};
/// Colour of the contact-count curve.
constexpr Color timeline_contacts_color{0.00f, 0.45f, 0.70f, 1.0f};
/// Colour of the penetration curve.
constexpr Color timeline_penetration_color{0.80f, 0.47f, 0.65f, 1.0f};

/// Height of the strip for a frame `width` pixels wide, pixels (grows with `frame_scale`).
int timeline_height(int width, int height);

/// Draws the strip over the renderer's whole viewport (a camera of 1 pixel per metre centred
/// on the viewport): a panel, the three curves over `samples` (in step order, the whole run),
/// a legend line with each curve's range, and a vertical mark at `current_step`. Text and lines
/// at integer `scale`.
void draw_timeline(PrimitiveRenderer& renderer, const std::vector<TimelineSample>& samples,
                   std::int64_t current_step, const ThemePalette& palette, int scale);

}  // namespace impulse2d::render
