#pragma once
/// @file float4.h
/// Four floats computed side by side (SSE2 on x86-64, four scalar lanes elsewhere): what the CPU
/// rasteriser (software_raster.cpp) uses to shade and blend four pixels of a row at once. Every
/// operation is the IEEE operation the scalar code does, lane by lane, in the same order, so the
/// pixels are bit-identical to shading them one by one; `min` and `max` keep `std::min` and
/// `std::max`'s operand order (the first operand when the comparison is false, NaN included).

#include <cmath>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impulse2d::render {

#if defined(__SSE2__)

/// Four floats in one SSE register.
struct Float4 {
  __m128 v;  ///< the lanes
  /// The lanes of `lanes`.
  Float4(__m128 lanes) : v(lanes) {}
  /// Every lane `value`: scalars mix with `Float4`s in the operators below.
  Float4(float value) : v(_mm_set1_ps(value)) {}
};

/// Every lane `value`.
inline Float4 splat(float value) { return Float4(value); }
/// Lanes `first`, `first` + 1, `first` + 2, `first` + 3 (exact for |first| < 2^24).
inline Float4 ramp(float first) { return {_mm_add_ps(_mm_set1_ps(first), _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f))}; }
/// Lane-wise sum.
inline Float4 operator+(Float4 a, Float4 b) { return {_mm_add_ps(a.v, b.v)}; }
/// Lane-wise difference.
inline Float4 operator-(Float4 a, Float4 b) { return {_mm_sub_ps(a.v, b.v)}; }
/// Lane-wise product.
inline Float4 operator*(Float4 a, Float4 b) { return {_mm_mul_ps(a.v, b.v)}; }
/// Lane-wise quotient.
inline Float4 operator/(Float4 a, Float4 b) { return {_mm_div_ps(a.v, b.v)}; }
/// 1 in the first `count` lanes (0..4), 0 in the others.
inline Float4 first_lanes(int count) {
  const __m128 below = _mm_cmplt_ps(_mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f), _mm_set1_ps(static_cast<float>(count)));
  return {_mm_and_ps(below, _mm_set1_ps(1.0f))};
}
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

/// The byte channels of four RGBA pixels as floats, one channel a `Float4`, and back.
struct Pixels4 {
  Float4 r;  ///< red, 0..255, integral
  Float4 g;  ///< green, 0..255, integral
  Float4 b;  ///< blue, 0..255, integral
  Float4 a;  ///< alpha, 0..255, integral
};

/// Four RGBA pixels from `bytes` (16 bytes).
inline Pixels4 load_pixels(const std::uint8_t* bytes) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i packed = _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes));
  const __m128i low = _mm_unpacklo_epi8(packed, zero);
  const __m128i high = _mm_unpackhi_epi8(packed, zero);
  __m128 p0 = _mm_cvtepi32_ps(_mm_unpacklo_epi16(low, zero));
  __m128 p1 = _mm_cvtepi32_ps(_mm_unpackhi_epi16(low, zero));
  __m128 p2 = _mm_cvtepi32_ps(_mm_unpacklo_epi16(high, zero));
  __m128 p3 = _mm_cvtepi32_ps(_mm_unpackhi_epi16(high, zero));
  _MM_TRANSPOSE4_PS(p0, p1, p2, p3);
  return Pixels4{p0, p1, p2, p3};
}

/// Stores four RGBA pixels to `bytes` (16 bytes): each channel of `pixels` converted with
/// truncation toward zero and its low byte kept, as `static_cast<std::uint8_t>` of a float does;
/// a pixel whose lane of `alpha` is not above 0 (or NaN) keeps the bytes of `old`.
inline void store_pixels(std::uint8_t* bytes, const Pixels4& pixels, Float4 alpha, const Pixels4& old) {
  const auto channel = [](Float4 value) { return _mm_and_si128(_mm_cvttps_epi32(value.v), _mm_set1_epi32(0xFF)); };
  const auto pack = [&](const Pixels4& p) {
    return _mm_or_si128(_mm_or_si128(channel(p.r), _mm_slli_epi32(channel(p.g), 8)),
                        _mm_or_si128(_mm_slli_epi32(channel(p.b), 16), _mm_slli_epi32(channel(p.a), 24)));
  };
  const __m128i write = _mm_castps_si128(_mm_cmpgt_ps(alpha.v, _mm_setzero_ps()));
  const __m128i result = _mm_or_si128(_mm_and_si128(write, pack(pixels)), _mm_andnot_si128(write, pack(old)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(bytes), result);
}

#else

/// Four floats, lane by lane.
struct Float4 {
  float v[4];  ///< the lanes
  Float4() = default;
  /// Every lane `value`: scalars mix with `Float4`s in the operators below.
  Float4(float value) : v{value, value, value, value} {}
};

namespace float4_detail {
/// The `Float4` whose lane i is `f(i)`.
template <typename F>
inline Float4 lanes(F f) {
  Float4 result;
  for (int i = 0; i < 4; ++i) result.v[i] = f(i);
  return result;
}
}  // namespace float4_detail

/// Every lane `value`.
inline Float4 splat(float value) { return Float4(value); }
/// Lanes `first`, `first` + 1, `first` + 2, `first` + 3 (exact for |first| < 2^24).
inline Float4 ramp(float first) { return float4_detail::lanes([&](int i) { return first + static_cast<float>(i); }); }
/// Lane-wise sum.
inline Float4 operator+(Float4 a, Float4 b) { return float4_detail::lanes([&](int i) { return a.v[i] + b.v[i]; }); }
/// Lane-wise difference.
inline Float4 operator-(Float4 a, Float4 b) { return float4_detail::lanes([&](int i) { return a.v[i] - b.v[i]; }); }
/// Lane-wise product.
inline Float4 operator*(Float4 a, Float4 b) { return float4_detail::lanes([&](int i) { return a.v[i] * b.v[i]; }); }
/// Lane-wise quotient.
inline Float4 operator/(Float4 a, Float4 b) { return float4_detail::lanes([&](int i) { return a.v[i] / b.v[i]; }); }
/// 1 in the first `count` lanes (0..4), 0 in the others.
inline Float4 first_lanes(int count) {
  return float4_detail::lanes([&](int i) { return i < count ? 1.0f : 0.0f; });
}
/// `std::min(a, b)` lane by lane: (b < a) ? b : a.
inline Float4 min(Float4 a, Float4 b) {
  return float4_detail::lanes([&](int i) { return b.v[i] < a.v[i] ? b.v[i] : a.v[i]; });
}
/// `std::max(a, b)` lane by lane: (a < b) ? b : a.
inline Float4 max(Float4 a, Float4 b) {
  return float4_detail::lanes([&](int i) { return a.v[i] < b.v[i] ? b.v[i] : a.v[i]; });
}
/// `std::abs` lane by lane.
inline Float4 abs(Float4 a) { return float4_detail::lanes([&](int i) { return std::abs(a.v[i]); }); }
/// `std::sqrt` lane by lane.
inline Float4 sqrt(Float4 a) { return float4_detail::lanes([&](int i) { return std::sqrt(a.v[i]); }); }
/// Whether any lane is above 0 (NaN is not).
inline bool any_positive(Float4 a) { return a.v[0] > 0.0f || a.v[1] > 0.0f || a.v[2] > 0.0f || a.v[3] > 0.0f; }

/// The byte channels of four RGBA pixels as floats, one channel a `Float4`, and back.
struct Pixels4 {
  Float4 r;  ///< red, 0..255, integral
  Float4 g;  ///< green, 0..255, integral
  Float4 b;  ///< blue, 0..255, integral
  Float4 a;  ///< alpha, 0..255, integral
};

/// Four RGBA pixels from `bytes` (16 bytes).
inline Pixels4 load_pixels(const std::uint8_t* bytes) {
  const auto channel = [&](int c) {
    return float4_detail::lanes([&](int i) { return static_cast<float>(bytes[4 * i + c]); });
  };
  return Pixels4{channel(0), channel(1), channel(2), channel(3)};
}

/// Stores four RGBA pixels to `bytes` (16 bytes): each channel of `pixels` converted as
/// `static_cast<std::uint8_t>` of a float; a pixel whose lane of `alpha` is not above 0 (or NaN)
/// keeps the bytes of `old`.
inline void store_pixels(std::uint8_t* bytes, const Pixels4& pixels, Float4 alpha, const Pixels4& old) {
  for (int i = 0; i < 4; ++i) {
    const Pixels4& from = alpha.v[i] > 0.0f ? pixels : old;
    bytes[4 * i] = static_cast<std::uint8_t>(from.r.v[i]);
    bytes[4 * i + 1] = static_cast<std::uint8_t>(from.g.v[i]);
    bytes[4 * i + 2] = static_cast<std::uint8_t>(from.b.v[i]);
    bytes[4 * i + 3] = static_cast<std::uint8_t>(from.a.v[i]);
  }
}

#endif

}  // namespace impulse2d::render
