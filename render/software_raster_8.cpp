/// @file software_raster_8.cpp
// The CPU rasteriser eight pixels at a time, x86-64 only: render/CMakeLists.txt compiles this
// file alone with -mavx2 (no FMA: the lanes must round as the four-lane drawing does).
#if defined(__x86_64__)

#include "render/software_raster_8.h"

#include "render/float8.h"
#include "render/software_raster_lanes.h"

namespace impulse2d::render {

bool software_raster_8_available() { return __builtin_cpu_supports("avx2"); }

void draw_band_8(const SoftwareBatch& batch, const std::vector<std::uint32_t>& band, int first_row, int last_row,
                 Frame& frame) {
  draw_band<Float8>(batch, band, first_row, last_row, frame);
}

}  // namespace impulse2d::render

#endif
