#pragma once
/// @file run_limits.h
/// Budgets of one command, checked before any work starts, so a typo cannot ask for hours
/// of stepping or gigabytes of pixels (README, "Limits").

#include <cstdint>

namespace impulse2d::demos::limits {

/// Longest run, steps (46 hours of simulated time at 60 steps per second).
constexpr std::int64_t max_steps = 10'000'000;
/// Most frames one `render` writes.
constexpr std::int64_t max_frames = 100'000;
/// Most pixels in one rendered frame (4096 x 4096; 64 MiB of RGBA).
constexpr std::int64_t max_frame_pixels = 4096ll * 4096;
/// Longest side of a contact sheet, pixels (the offscreen renderer's limit).
constexpr int max_sheet_side = 8192;
/// Most pixels in a contact sheet (its tiles are held in memory too: about 2 x 128 MiB).
constexpr std::int64_t max_sheet_pixels = 8192ll * 4096;
/// Most rows (samples x moving bodies) one `trace` prints.
constexpr std::int64_t max_trace_rows = 10'000'000;

}  // namespace impulse2d::demos::limits
