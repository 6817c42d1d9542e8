#pragma once
/// @file frame.h
/// What the renderer draws into: the project's one image type (image/image.h), always opaque.

#include "image/image.h"

namespace impulse2d::render {

/// One rendered frame: an `Image` the renderer fills, rows top to bottom, alpha 255.
using Frame = image::Image;
/// One pixel of a frame.
using Pixel = image::Rgba;

}  // namespace impulse2d::render
