#pragma once
/// @file palette.h
/// Themes: background, HUD and the colours of every drawn role. Overlay colours come from
/// the Okabe-Ito set, which stays distinguishable under the common colour-vision deficiencies.

#include "core/debug_draw.h"

#include <optional>
#include <string>

namespace impulse2d::render {

/// The background a frame is drawn on.
enum class Theme {
  Light,  ///< near-white background, dark outlines
  Dark,   ///< near-black background, light outlines
};

/// Every colour of a frame under one theme.
struct ThemePalette {
  Color background;    ///< frame clear colour (opaque)
  Color hud_text;      ///< HUD and legend text
  Color hud_panel;     ///< translucent panel behind the HUD and legend
  Color trail;         ///< motion trails (drawn fading towards the oldest point)
  DebugPalette debug;  ///< what `World::draw` uses for shapes and overlays
};

/// The palette of `theme`.
ThemePalette theme_palette(Theme theme);

/// "light" or "dark" (case-sensitive); nothing for anything else.
std::optional<Theme> parse_theme(const std::string& name);

/// The name `parse_theme` accepts for `theme`.
const char* theme_name(Theme theme);

}  // namespace impulse2d::render
