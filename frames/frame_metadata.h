#pragma once
/// @file frame_metadata.h
/// What a rendered frame's PNG says about itself (tEXt chunks, golden/png_text.h):
/// scene, parameters, step, simulated time, physics state hash, renderer and program version.
/// Written by `impulse2d render` and the golden suite alike, read by `impulse2d diff`.

#include <string>

#include "image/png_text.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// The metadata of a frame of `scene` (its name, with the scene file in brackets for a file)
/// drawn from `world`'s current state. `parameters` is the overrides as "rows=8 seed=3"
/// (empty: "defaults"); `renderer` describes the renderer
/// (`golden::RendererFingerprint::describe`: "GL_RENDERER / GL_VERSION").
image::PngText frame_metadata(const std::string& scene, const std::string& parameters,
                               const World& world, const std::string& renderer);

}  // namespace impulse2d::demos
