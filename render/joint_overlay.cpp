/// @file joint_overlay.cpp
#include "render/joint_overlay.h"

#include "core/world.h"
#include "render/contact_overlay.h"
#include "render/primitive_renderer.h"

namespace impulse2d::render {
namespace {

// Passes `World::draw`'s marks on to the renderer, cutting arrows as the contact arrows are.
class ClampedArrows final : public DebugDraw {
 public:
  ClampedArrows(PrimitiveRenderer& renderer, float max_pixels) : renderer_(renderer), max_pixels_(max_pixels) {}
  void draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) override {
    renderer_.draw_solid_polygon(vertices, count, fill, outline);
  }
  void draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) override {
    renderer_.draw_solid_circle(center, radius, axis, fill, outline);
  }
  void draw_segment(vec2 from, vec2 to, Color color) override { renderer_.draw_segment(from, to, color); }
  void draw_arrow(vec2 from, vec2 to, Color color) override {
    draw_clamped_arrow(renderer_, from, to, color, max_pixels_);
  }
  void draw_point(vec2 position, float size_pixels, Color color) override {
    renderer_.draw_point(position, size_pixels, color);
  }
  void draw_text(vec2 position, const std::string& text, Color color) override {
    renderer_.draw_text(position, text, color);
  }

 private:
  PrimitiveRenderer& renderer_;
  float max_pixels_;
};

}  // namespace

void draw_joints_overlay(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                         float max_arrow_pixels) {
  if ((options.flags & draw_joints) == 0 || world.joint_count() == 0) return;
  DebugDrawOptions joints = options;
  joints.flags = draw_joints;
  ClampedArrows draw(renderer, max_arrow_pixels);
  world.draw(draw, joints);
}

}  // namespace impulse2d::render
