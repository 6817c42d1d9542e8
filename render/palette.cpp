/// @file palette.cpp
#include "render/palette.h"

namespace impulse2d::render {

namespace {

constexpr Color rgb(int r, int g, int b, float a = 1.0f) {
  return Color{static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f,
               static_cast<float>(b) / 255.0f, a};
}

// Okabe & Ito (2008), "Color Universal Design".
constexpr Color kOrange = rgb(230, 159, 0);
constexpr Color kSkyBlue = rgb(86, 180, 233);
constexpr Color kBluishGreen = rgb(0, 158, 115);
constexpr Color kYellow = rgb(240, 228, 66);
constexpr Color kBlue = rgb(0, 114, 178);
constexpr Color kVermillion = rgb(213, 94, 0);
constexpr Color kReddishPurple = rgb(204, 121, 167);

ThemePalette light_palette() {
  ThemePalette p;
  p.background = rgb(250, 250, 247);
  p.hud_text = rgb(20, 20, 28);
  p.hud_panel = rgb(255, 255, 255, 0.8f);
  p.trail = rgb(90, 90, 100, 0.8f);
  DebugPalette& d = p.debug;
  d.dynamic_fill = rgb(190, 214, 236);
  d.kinematic_fill = rgb(196, 228, 200);
  d.static_fill = rgb(196, 196, 196);
  d.sleeping_fill = rgb(226, 229, 233);
  d.outline = rgb(38, 42, 56);
  d.aabb = rgb(120, 120, 130, 0.9f);
  d.contact_point = kVermillion;
  d.contact_normal = kBlue;
  d.normal_impulse = kOrange;
  d.friction_impulse = kBluishGreen;
  d.penetration = kReddishPurple;
  d.velocity = kSkyBlue;
  d.center_of_mass = rgb(0, 0, 0);
  d.broad_phase_pair = rgb(180, 160, 0, 0.6f);  // Okabe-Ito yellow darkened to read on white
  d.label = rgb(20, 20, 28);
  d.joint = rgb(110, 50, 150);
  d.joint_reaction = rgb(200, 30, 90);
  d.sensor_fill = rgb(240, 228, 66, 0.35f);  // Okabe-Ito yellow, see-through
  d.event_touch = rgb(0, 120, 120);
  d.event_hit = rgb(190, 0, 0);
  d.event_sensor = rgb(160, 130, 0);
  return p;
}

ThemePalette dark_palette() {
  ThemePalette p;
  p.background = rgb(24, 26, 32);
  p.hud_text = rgb(232, 232, 236);
  p.hud_panel = rgb(0, 0, 0, 0.6f);
  p.trail = rgb(200, 200, 210, 0.8f);
  DebugPalette& d = p.debug;
  d.dynamic_fill = rgb(52, 78, 110);
  d.kinematic_fill = rgb(50, 94, 62);
  d.static_fill = rgb(78, 80, 86);
  d.sleeping_fill = rgb(48, 52, 60);
  d.outline = rgb(214, 218, 228);
  d.aabb = rgb(150, 150, 160, 0.9f);
  d.contact_point = kVermillion;
  d.contact_normal = kSkyBlue;  // Okabe-Ito blue is too dark on black
  d.normal_impulse = kOrange;
  d.friction_impulse = kBluishGreen;
  d.penetration = kReddishPurple;
  d.velocity = kYellow;
  d.center_of_mass = rgb(255, 255, 255);
  d.broad_phase_pair = rgb(170, 170, 190, 0.45f);  // neutral: yellow is taken by velocity
  d.label = rgb(232, 232, 236);
  d.joint = rgb(205, 160, 255);
  d.joint_reaction = rgb(255, 110, 150);
  d.sensor_fill = rgb(240, 228, 66, 0.25f);
  d.event_touch = rgb(90, 220, 210);
  d.event_hit = rgb(255, 90, 90);
  d.event_sensor = rgb(240, 228, 66);
  return p;
}

}  // namespace

ThemePalette theme_palette(Theme theme) {
  return theme == Theme::Dark ? dark_palette() : light_palette();
}

std::optional<Theme> parse_theme(const std::string& name) {
  if (name == "light") return Theme::Light;
  if (name == "dark") return Theme::Dark;
  return std::nullopt;
}

const char* theme_name(Theme theme) { return theme == Theme::Dark ? "dark" : "light"; }

}  // namespace impulse2d::render
