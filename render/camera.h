#pragma once
/// @file camera.h
/// Orthographic camera: world metres (y up) to pixels, built with GLM.

#include "core/math.h"
#include "core/shape.h"

#include <glm/mat4x4.hpp>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

/// Maps world coordinates (metres, y up) onto a width x height image with a uniform scale.
/// Pixel coordinates have their origin at the image's top-left corner, x right, y down, and
/// pixel (i, j) covers [i, i+1) x [j, j+1) (its centre is at i + 0.5, j + 0.5).
class Camera {
 public:
  /// A camera showing `bounds` whole and centred, leaving at least `margin_pixels` on every
  /// side. Zero-size bounds get 50 pixels per metre. Throws `RenderError` when the image is
  /// smaller than twice the margin, or for non-finite bounds.
  static Camera fit(const Aabb& bounds, int width, int height, float margin_pixels = 16.0f);
  /// As `fit`, into the image less a band `top_pixels` tall along its top edge and one
  /// `bottom_pixels` tall along its bottom edge (kept free for the HUD and legend): `bounds`
  /// whole and centred in what is left, at least `margin_pixels` from its every side. Throws
  /// `RenderError` when the bands and margins leave no room, or for non-finite values.
  static Camera fit_between_bands(const Aabb& bounds, int width, int height, float margin_pixels,
                                  float top_pixels, float bottom_pixels);
  /// A camera with `center` (metres) at the image centre and `pixels_per_metre` zoom (> 0).
  /// Throws `RenderError` for a non-positive size or zoom, or non-finite values.
  static Camera centered(vec2 center, float pixels_per_metre, int width, int height);

  /// The same camera moved so that `center` (metres) is at the image centre (to follow a body).
  Camera with_center(vec2 center) const;

  /// World point at the image centre, metres.
  vec2 center() const { return center_; }
  /// Zoom, pixels per metre.
  float pixels_per_metre() const { return pixels_per_metre_; }
  /// Image width, pixels.
  int width() const { return width_; }
  /// Image height, pixels.
  int height() const { return height_; }
  /// The world rectangle the image shows, metres.
  Aabb visible_bounds() const;
  /// Orthographic projection (glm::ortho) from world metres to GL clip space.
  glm::mat4 world_to_clip() const;
  /// World point (metres) to pixel coordinates (top-left origin, y down).
  vec2 world_to_pixel(vec2 world) const;
  /// Pixel coordinates (top-left origin, y down) to the world point, metres.
  vec2 pixel_to_world(vec2 pixel) const;

 private:
  Camera(vec2 center, float pixels_per_metre, int width, int height)
      : center_(center), pixels_per_metre_(pixels_per_metre), width_(width), height_(height) {}

  vec2 center_{0.0f, 0.0f};
  float pixels_per_metre_ = 1.0f;
  int width_ = 1;
  int height_ = 1;
};

/// The union of the world-space bounds of every living body's shape, metres. An empty world
/// gives the box from (-1, -1) to (1, 1).
Aabb world_bounds(const World& world);

}  // namespace impulse2d::render
