/// @file software_raster.cpp
#include "render/software_raster.h"

#include "render/float4.h"
#include "render/software_raster_8.h"
#include "render/software_raster_lanes.h"

#include <algorithm>
#include <cstddef>

namespace impulse2d::render {

void SoftwareBatch::clear() {
  primitives.clear();
  shapes.clear();
  polygons.clear();
  texts.clear();
  fill_quads.clear();
}

bool SoftwareRaster::eight_lanes_available() {
#if defined(__x86_64__)
  return software_raster_8_available();
#else
  return false;
#endif
}

SoftwareRaster::SoftwareRaster(int thread_count, RasterLanes lanes)
    : pool_(thread_count),
      lanes_(lanes == RasterLanes::eight && eight_lanes_available() ? RasterLanes::eight : RasterLanes::four) {}

void SoftwareRaster::draw(const SoftwareBatch& batch, Frame& frame) {
  if (batch.primitives.empty() || frame.height <= 0) return;
  // Each band's primitives, in drawing order.
  const int band_count = (frame.height + band_rows - 1) / band_rows;
  band_primitives_.resize(static_cast<std::size_t>(band_count));
  for (std::vector<std::uint32_t>& band : band_primitives_) band.clear();
  for (std::size_t i = 0; i < batch.primitives.size(); ++i) {
    const SoftwarePrimitive& primitive = batch.primitives[i];
    for (int band = primitive.bottom / band_rows; band <= primitive.top / band_rows; ++band) {
      band_primitives_[static_cast<std::size_t>(band)].push_back(static_cast<std::uint32_t>(i));
    }
  }
  auto* draw_lanes = &draw_band<Float4>;
#if defined(__x86_64__)
  if (lanes_ == RasterLanes::eight) draw_lanes = &draw_band_8;
#endif
  pool_.run(band_count, [&](int band) {
    const int first_row = band * band_rows;
    const int last_row = std::min(first_row + band_rows, frame.height) - 1;
    draw_lanes(batch, band_primitives_[static_cast<std::size_t>(band)], first_row, last_row, frame);
  });
}

}  // namespace impulse2d::render
