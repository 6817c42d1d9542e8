/// @file camera.cpp
#include "render/camera.h"

#include "core/world.h"
#include "render/render_error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse2d::render {

namespace {

constexpr float kDefaultPixelsPerMetre = 50.0f;

void check_size(const char* caller, int width, int height) {
  if (width < 1 || height < 1) {
    throw RenderError(std::string(caller) + ": image size " + std::to_string(width) + "x" +
                      std::to_string(height) + " must be at least 1x1 pixels");
  }
}

}  // namespace

Camera Camera::fit(const Aabb& bounds, int width, int height, float margin_pixels) {
  return fit_between_bands(bounds, width, height, margin_pixels, 0.0f, 0.0f);
}

Camera Camera::fit_between_bands(const Aabb& bounds, int width, int height, float margin_pixels, float top_pixels,
                                 float bottom_pixels) {
  check_size("Camera::fit", width, height);
  if (!is_finite(bounds.lower) || !is_finite(bounds.upper) || !std::isfinite(margin_pixels) ||
      margin_pixels < 0.0f || !std::isfinite(top_pixels) || !std::isfinite(bottom_pixels) || top_pixels < 0.0f ||
      bottom_pixels < 0.0f) {
    throw RenderError("Camera::fit: bounds, margin and bands must be finite (margin and bands >= 0)");
  }
  const float usable_width = static_cast<float>(width) - 2.0f * margin_pixels;
  const float usable_height = static_cast<float>(height) - 2.0f * margin_pixels - top_pixels - bottom_pixels;
  if (usable_width <= 0.0f || usable_height <= 0.0f) {
    throw RenderError("Camera::fit: margin of " + std::to_string(margin_pixels) +
                      " pixels leaves no room in a " + std::to_string(width) + "x" +
                      std::to_string(height) + " image");
  }
  const vec2 extent = bounds.upper - bounds.lower;
  float zoom = kDefaultPixelsPerMetre;
  if (extent.x > 0.0f && extent.y > 0.0f) {
    zoom = std::min(usable_width / extent.x, usable_height / extent.y);
  } else if (extent.x > 0.0f) {
    zoom = usable_width / extent.x;
  } else if (extent.y > 0.0f) {
    zoom = usable_height / extent.y;
  }
  // The bounds' centre goes to the middle of the space between the bands: (top - bottom) / 2
  // pixels below the image centre.
  const vec2 shift(0.0f, 0.5f * (top_pixels - bottom_pixels) / zoom);
  return Camera(0.5f * (bounds.lower + bounds.upper) + shift, zoom, width, height);
}

Camera Camera::centered(vec2 center, float pixels_per_metre, int width, int height) {
  check_size("Camera::centered", width, height);
  if (!is_finite(center) || !std::isfinite(pixels_per_metre) || pixels_per_metre <= 0.0f) {
    throw RenderError("Camera::centered: centre must be finite and pixels_per_metre > 0 (got " +
                      std::to_string(pixels_per_metre) + ")");
  }
  return Camera(center, pixels_per_metre, width, height);
}

Camera Camera::with_center(vec2 center) const {
  return centered(center, pixels_per_metre_, width_, height_);
}

Aabb Camera::visible_bounds() const {
  const vec2 half(0.5f * static_cast<float>(width_) / pixels_per_metre_,
                  0.5f * static_cast<float>(height_) / pixels_per_metre_);
  return Aabb{center_ - half, center_ + half};
}

glm::mat4 Camera::world_to_clip() const {
  const Aabb visible = visible_bounds();
  return glm::ortho(visible.lower.x, visible.upper.x, visible.lower.y, visible.upper.y);
}

vec2 Camera::world_to_pixel(vec2 world) const {
  const vec2 offset = (world - center_) * pixels_per_metre_;
  return vec2(0.5f * static_cast<float>(width_) + offset.x, 0.5f * static_cast<float>(height_) - offset.y);
}

vec2 Camera::pixel_to_world(vec2 pixel) const {
  const vec2 offset(pixel.x - 0.5f * static_cast<float>(width_), 0.5f * static_cast<float>(height_) - pixel.y);
  return center_ + offset / pixels_per_metre_;
}

Aabb world_bounds(const World& world) {
  bool any = false;
  Aabb total{vec2(-1.0f, -1.0f), vec2(1.0f, 1.0f)};
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    // A compound body's bounds cover all its shapes (kept by the world).
    const Aabb box = body.shape_count > 0 ? body.aabb : compute_aabb(*body.shape, body.transform);
    if (!any) {
      total = box;
      any = true;
    } else {
      total.lower = glm::min(total.lower, box.lower);
      total.upper = glm::max(total.upper, box.upper);
    }
  }
  return total;
}

}  // namespace impulse2d::render
