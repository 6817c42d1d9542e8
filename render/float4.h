#pragma once
/// @file float4.h
/// Four floats computed side by side (SSE2 on x86-64, four scalar lanes elsewhere): what the CPU
/// rasteriser (software_raster_lanes.h) uses to shade and blend four pixels of a row at once.
/// Every operation is the IEEE operation the scalar code does, lane by lane, in the same order, so
/// the pixels are bit-identical to shading them one by one; `min` and `max` keep `std::min` and
/// `std::max`'s operand order (the first operand when the comparison is false, NaN included).
/// float8.h is the same for eight lanes.

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impulse2d::render {

struct Pixels4;

/// 1 when bit `min(max(index, 0), 255)` of the 256 bits `words` (bit j is bit j % 32 of word
/// j / 32) is set, else 0.
inline float bit_of(const std::uint32_t* words, std::int32_t index) {
  const std::int32_t bit = index < 0 ? 0 : (index > 255 ? 255 : index);
  return static_cast<float>((words[bit >> 5] >> (bit & 31)) & 1u);
}

#if defined(__SSE2__)

/// Four floats in one SSE register.
struct Float4 {
  static constexpr int width = 4;  ///< lanes
  using Pixels = Pixels4;          ///< four pixels' bytes, loaded for blending
  __m128 v;                        ///< the lanes
  /// The lanes of `lanes`.
  Float4(__m128 lanes) : v(lanes) {}
  /// Every lane `value`: scalars mix with `Float4`s in the operators below.
  Float4(float value) : v(_mm_set1_ps(value)) {}
  /// Lanes `first`, `first` + 1, `first` + 2, `first` + 3 (exact for |first| < 2^24).
  static Float4 ramp(float first) { return {_mm_add_ps(_mm_set1_ps(first), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f))}; }
  /// 1 in the first `count` lanes (0..4), 0 in the others.
  static Float4 first_lanes(int count) {
    const __m128 below = _mm_cmplt_ps(_mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f), _mm_set1_ps(static_cast<float>(count)));
    return {_mm_and_ps(below, _mm_set1_ps(1.0f))};
  }
  /// Lane i `bit_of(words, base[i] + offset)`.
  static Float4 bits(const std::uint32_t* words, const std::int32_t* base, std::int32_t offset) {
    return {_mm_set_ps(bit_of(words, base[3] + offset), bit_of(words, base[2] + offset), bit_of(words, base[1] + offset),
                       bit_of(words, base[0] + offset))};
  }
};

/// Lane-wise sum.
inline Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
/// Lane-wise difference.
inline Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
/// Lane-wise product.
inline Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
/// Lane-wise quotient.
inline Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
/// `std::min(a, b)` lane by lane: (b < a) ? b : a.
inline Float4 min(Float4 a, Float4 b) { return {_mm_min_ps(b.v, a.v)}; }
/// `std::max(a, b)` lane by lane: (a < b) ? b : a.
inline Float4 max(Float4 a, Float4 b) { return {_mm_max_ps(b.v, a.v)}; }
/// `std::abs` lane by lane (clears the sign bit).
inline Float4 abs(Float4 a) { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)}; }
/// `std::sqrt` lane by lane (correctly rounded, as the scalar square root).
inline Float4 sqrt(Float4 a) { return {_mm_sqrt_ps(a.v)}; }
/// Whether any lane is above 0 (NaN is not).
inline bool any_positive(Float4 a) { return _mm_movemask_ps(_mm_cmpgt_ps(a.v, _mm_setzero_ps())) != 0; }

/// Four RGBA pixels as read from a frame: their bytes, and the colour channels as floats (one
/// channel a `Float4`) for blending.
struct Pixels4 {
  __m128i bytes;  ///< the 16 bytes, pixel i in lane i
  Float4 r;       ///< red, 0..255, integral
  Float4 g;       ///< green, 0..255, integral
  Float4 b;       ///< blue, 0..255, integral

  /// Four RGBA pixels from `at` (16 bytes).
  static Pixels4 load(const std::uint8_t* at) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
    const __m128i low = _mm_set1_epi32(0xFF);
    return Pixels4{bytes, _mm_cvtepi32_ps(_mm_and_si128(bytes, low)),
                   _mm_cvtepi32_ps(_mm_and_si128(_mm_srli_epi32(bytes, 8), low)),
                   _mm_cvtepi32_ps(_mm_and_si128(_mm_srli_epi32(bytes, 16), low))};
  }

  /// Stores these pixels to `at` (16 bytes) with colour channels `red`, `green`, `blue`, each
  /// converted with truncation toward zero and its low byte kept, as `static_cast<std::uint8_t>`
  /// of a float does, and alpha as it was; a pixel whose lane of `alpha` is not above 0 (or NaN)
  /// keeps its bytes.
  void store(std::uint8_t* at, Float4 red, Float4 green, Float4 blue, Float4 alpha) const {
    const __m128i low = _mm_set1_epi32(0xFF);
    const auto channel = [&](Float4 value) { return _mm_and_si128(_mm_cvttps_epi32(value.v), low); };
    const __m128i colour = _mm_or_si128(_mm_or_si128(channel(red), _mm_slli_epi32(channel(green), 8)),
                                        _mm_or_si128(_mm_slli_epi32(channel(blue), 16),
                                                     _mm_andnot_si128(_mm_set1_epi32(0x00FFFFFF), bytes)));
    const __m128i write = _mm_castps_si128(_mm_cmpgt_ps(alpha.v, _mm_setzero_ps()));
    const __m128i result = _mm_or_si128(_mm_and_si128(write, colour), _mm_andnot_si128(write, bytes));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at), result);
  }

  /// Writes the red, green and blue bytes of `rgb` (bytes 0, 1, 2; byte 3 unused) to the pixels
  /// at `at` (16 bytes) whose lane of `where` is above 0, alpha as it was; the others keep their
  /// bytes.
  static void paint(std::uint8_t* at, Float4 where, std::uint32_t rgb) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
    const __m128i colour = _mm_or_si128(_mm_set1_epi32(static_cast<int>(rgb & 0x00FFFFFFu)),
                                        _mm_andnot_si128(_mm_set1_epi32(0x00FFFFFF), bytes));
    const __m128i write = _mm_castps_si128(_mm_cmpgt_ps(where.v, _mm_setzero_ps()));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at),
                     _mm_or_si128(_mm_and_si128(write, colour), _mm_andnot_si128(write, bytes)));
  }
};

#else

/// Four floats, lane by lane.
struct Float4 {
  static constexpr int width = 4;  ///< lanes
  using Pixels = Pixels4;          ///< four pixels' bytes, loaded for blending
  float v[4];                      ///< the lanes
  Float4() = default;
  /// Every lane `value`: scalars mix with `Float4`s in the operators below.
  Float4(float value) : v{value, value, value, value} {}
  /// The `Float4` whose lane i is `f(i)`.
  template <typename F>
  static Float4 lanes(F f) {
    Float4 result;
    for (int i = 0; i < 4; ++i) result.v[i] = f(i);
    return result;
  }
  /// Lanes `first`, `first` + 1, `first` + 2, `first` + 3 (exact for |first| < 2^24).
  static Float4 ramp(float first) { return lanes([&](int i) { return first + static_cast<float>(i); }); }
  /// 1 in the first `count` lanes (0..4), 0 in the others.
  static Float4 first_lanes(int count) { return lanes([&](int i) { return i < count ? 1.0f : 0.0f; }); }
  /// Lane i `bit_of(words, base[i] + offset)`.
  static Float4 bits(const std::uint32_t* words, const std::int32_t* base, std::int32_t offset) {
    return lanes([&](int i) { return bit_of(words, base[i] + offset); });
  }
};

/// Lane-wise sum.
inline Float4 operator+(Float4 a, Float4 b) { return Float4::lanes([&](int i) { return a.v[i] + b.v[i]; }); }
/// Lane-wise difference.
inline Float4 operator-(Float4 a, Float4 b) { return Float4::lanes([&](int i) { return a.v[i] - b.v[i]; }); }
/// Lane-wise product.
inline Float4 operator*(Float4 a, Float4 b) { return Float4::lanes([&](int i) { return a.v[i] * b.v[i]; }); }
/// Lane-wise quotient.
inline Float4 operator/(Float4 a, Float4 b) { return Float4::lanes([&](int i) { return a.v[i] / b.v[i]; }); }
/// `std::min(a, b)` lane by lane: (b < a) ? b : a.
inline Float4 min(Float4 a, Float4 b) {
  return Float4::lanes([&](int i) { return b.v[i] < a.v[i] ? b.v[i] : a.v[i]; });
}
/// `std::max(a, b)` lane by lane: (a < b) ? b : a.
inline Float4 max(Float4 a, Float4 b) {
  return Float4::lanes([&](int i) { return a.v[i] < b.v[i] ? b.v[i] : a.v[i]; });
}
/// `std::abs` lane by lane.
inline Float4 abs(Float4 a) { return Float4::lanes([&](int i) { return std::abs(a.v[i]); }); }
/// `std::sqrt` lane by lane.
inline Float4 sqrt(Float4 a) { return Float4::lanes([&](int i) { return std::sqrt(a.v[i]); }); }
/// Whether any lane is above 0 (NaN is not).
inline bool any_positive(Float4 a) { return a.v[0] > 0.0f || a.v[1] > 0.0f || a.v[2] > 0.0f || a.v[3] > 0.0f; }

/// Four RGBA pixels as read from a frame: their bytes, and the colour channels as floats (one
/// channel a `Float4`) for blending.
struct Pixels4 {
  std::uint8_t bytes[16];  ///< pixel i at 4 i
  Float4 r;                ///< red, 0..255, integral
  Float4 g;                ///< green, 0..255, integral
  Float4 b;                ///< blue, 0..255, integral

  /// Four RGBA pixels from `at` (16 bytes).
  static Pixels4 load(const std::uint8_t* at) {
    Pixels4 pixels;
    std::memcpy(pixels.bytes, at, sizeof pixels.bytes);
    const auto channel = [&](int c) { return Float4::lanes([&](int i) { return static_cast<float>(at[4 * i + c]); }); };
    pixels.r = channel(0);
    pixels.g = channel(1);
    pixels.b = channel(2);
    return pixels;
  }

  /// Stores these pixels to `at` (16 bytes) with colour channels `red`, `green`, `blue`, each
  /// converted as `static_cast<std::uint8_t>` of a float, and alpha as it was; a pixel whose lane
  /// of `alpha` is not above 0 (or NaN) keeps its bytes.
  void store(std::uint8_t* at, Float4 red, Float4 green, Float4 blue, Float4 alpha) const {
    std::memcpy(at, bytes, sizeof bytes);
    for (int i = 0; i < 4; ++i) {
      if (!(alpha.v[i] > 0.0f)) continue;
      at[4 * i] = static_cast<std::uint8_t>(red.v[i]);
      at[4 * i + 1] = static_cast<std::uint8_t>(green.v[i]);
      at[4 * i + 2] = static_cast<std::uint8_t>(blue.v[i]);
    }
  }

  /// Writes the red, green and blue bytes of `rgb` (bytes 0, 1, 2; byte 3 unused) to the pixels
  /// at `at` (16 bytes) whose lane of `where` is above 0, alpha as it was; the others keep their
  /// bytes.
  static void paint(std::uint8_t* at, Float4 where, std::uint32_t rgb) {
    for (int i = 0; i < 4; ++i) {
      if (!(where.v[i] > 0.0f)) continue;
      at[4 * i] = static_cast<std::uint8_t>(rgb);
      at[4 * i + 1] = static_cast<std::uint8_t>(rgb >> 8);
      at[4 * i + 2] = static_cast<std::uint8_t>(rgb >> 16);
    }
  }
};

#endif

}  // namespace impulse2d::render
