#pragma once
/// @file error.h
/// The exception the golden-image library throws: the image library's, since the golden tools'
/// failures (unreadable PNG files, sidecars, tolerance objects, environment variables, failed
/// writes) and the image library's are reported alike.

#include "image/error.h"

namespace impulse2d::golden {

/// Thrown for unreadable or invalid inputs and failed writes. The message names the file or
/// variable, the field where there is one, and the reason.
using GoldenError = image::ImageError;

}  // namespace impulse2d::golden
