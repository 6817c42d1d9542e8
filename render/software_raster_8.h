#pragma once
/// @file software_raster_8.h
/// The eight-lane (AVX2) drawing of a band of the CPU rasteriser, x86-64 only: software_raster_8.cpp
/// is compiled alone with -mavx2 (no FMA), and `SoftwareRaster` calls it only after
/// `software_raster_8_available()` said yes. Its bytes are those of the four-lane drawing.

#include "render/frame.h"
#include "render/software_raster.h"

#include <cstdint>
#include <vector>

namespace impulse2d::render {

#if defined(__x86_64__)
/// Whether this CPU has AVX2 (checked at run time).
bool software_raster_8_available();
/// Draws the primitives `band` (indices into `batch.primitives`, in drawing order) in window rows
/// [first_row, last_row] of `frame`, eight pixels of a row at a time; only when
/// `software_raster_8_available()`.
void draw_band_8(const SoftwareBatch& batch, const std::vector<std::uint32_t>& band, int first_row, int last_row,
                 Frame& frame);
#endif

}  // namespace impulse2d::render
