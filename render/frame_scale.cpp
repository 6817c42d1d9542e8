/// @file frame_scale.cpp
#include "render/frame_scale.h"

#include <algorithm>

namespace impulse2d::render {

int frame_scale(int width, int height) {
  return std::max(1, std::min(width, height) / frame_scale_step_pixels);
}

}  // namespace impulse2d::render
