#pragma once
/// @file float8.h
/// Eight floats computed side by side in one AVX register: what the CPU rasteriser
/// (software_raster_lanes.h) uses to shade and blend eight pixels of a row at once where the CPU
/// has AVX2. The same interface and the same IEEE operations as float4.h, lane by lane (no fused
/// multiply-add, no approximate reciprocal), so eight lanes give the bytes four do. Only for
/// files compiled with -mavx2 (software_raster_8.cpp).

#if defined(__AVX2__)

#include <immintrin.h>

#include <cstdint>

namespace impulse2d::render {

struct Pixels8;

/// Eight floats in one AVX register.
struct Float8 {
  static constexpr int width = 8;  ///< lanes
  using Pixels = Pixels8;          ///< eight pixels' bytes, loaded for blending
  __m256 v;                        ///< the lanes
  /// The lanes of `lanes`.
  Float8(__m256 lanes) : v(lanes) {}
  /// Every lane `value`: scalars mix with `Float8`s in the operators below.
  Float8(float value) : v(_mm256_set1_ps(value)) {}
  /// Lanes `first`, `first` + 1, ..., `first` + 7 (exact for |first| < 2^24).
  static Float8 ramp(float first) { return {_mm256_add_ps(_mm256_set1_ps(first), indices())}; }
  /// 1 in the first `count` lanes (0..8), 0 in the others.
  static Float8 first_lanes(int count) {
    const __m256 below = _mm256_cmp_ps(indices(), _mm256_set1_ps(static_cast<float>(count)), _CMP_LT_OQ);
    return {_mm256_and_ps(below, _mm256_set1_ps(1.0f))};
  }
  /// Two runs of four: lanes `low`, `low` + 1, `low` + 2, `low` + 3, then `high` ... `high` + 3: the
  /// columns of two spans of up to four pixels shaded as one group (each lane as `ramp` gives it).
  static Float8 ramp_halves(float low, float high) {
    return {_mm256_add_ps(_mm256_setr_ps(low, low, low, low, high, high, high, high), half_indices())};
  }
  /// `low` in lanes 0..3, `high` in lanes 4..7.
  static Float8 halves(float low, float high) {
    return {_mm256_setr_ps(low, low, low, low, high, high, high, high)};
  }
  /// 1 in the first `low_count` lanes (0..4) of lanes 0..3 and the first `high_count` of lanes
  /// 4..7, 0 in the others.
  static Float8 first_lanes_halves(int low_count, int high_count) {
    const __m256 counts = _mm256_setr_ps(static_cast<float>(low_count), static_cast<float>(low_count),
                                         static_cast<float>(low_count), static_cast<float>(low_count),
                                         static_cast<float>(high_count), static_cast<float>(high_count),
                                         static_cast<float>(high_count), static_cast<float>(high_count));
    return {_mm256_and_ps(_mm256_cmp_ps(half_indices(), counts, _CMP_LT_OQ), _mm256_set1_ps(1.0f))};
  }
  /// 1 in lane i when bit `min(max(base[i] + offset, 0), 255)` of the 256 bits `words` (bit j is
  /// bit j % 32 of word j / 32) is set, else 0.
  static Float8 bits(const std::uint32_t* words, const std::int32_t* base, std::int32_t offset) {
    const __m256i index = _mm256_min_epi32(
        _mm256_max_epi32(_mm256_add_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(base)),
                                          _mm256_set1_epi32(offset)),
                         _mm256_setzero_si256()),
        _mm256_set1_epi32(255));
    const __m256i word = _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(words)),
                                                     _mm256_srli_epi32(index, 5));
    const __m256i bit = _mm256_srlv_epi32(word, _mm256_and_si256(index, _mm256_set1_epi32(31)));
    return {_mm256_cvtepi32_ps(_mm256_and_si256(bit, _mm256_set1_epi32(1)))};
  }

 private:
  static __m256 indices() { return _mm256_set_ps(7.0f, 6.0f, 5.0f, 4.0f, 3.0f, 2.0f, 1.0f, 0.0f); }
  static __m256 half_indices() { return _mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 0.0f, 1.0f, 2.0f, 3.0f); }
};

/// Lane-wise sum.
inline Float8 operator+(Float8 a, Float8 b) { return {_mm256_add_ps(a.v, b.v)}; }
/// Lane-wise difference.
inline Float8 operator-(Float8 a, Float8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
/// Lane-wise product.
inline Float8 operator*(Float8 a, Float8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
/// Lane-wise quotient.
inline Float8 operator/(Float8 a, Float8 b) { return {_mm256_div_ps(a.v, b.v)}; }
/// `std::min(a, b)` lane by lane: (b < a) ? b : a.
inline Float8 min(Float8 a, Float8 b) { return {_mm256_min_ps(b.v, a.v)}; }
/// `std::max(a, b)` lane by lane: (a < b) ? b : a.
inline Float8 max(Float8 a, Float8 b) { return {_mm256_max_ps(b.v, a.v)}; }
/// `std::abs` lane by lane (clears the sign bit).
inline Float8 abs(Float8 a) { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)}; }
/// `std::sqrt` lane by lane (correctly rounded, as the scalar square root).
inline Float8 sqrt(Float8 a) { return {_mm256_sqrt_ps(a.v)}; }
/// Whether any lane is above 0 (NaN is not).
inline bool any_positive(Float8 a) {
  return _mm256_movemask_ps(_mm256_cmp_ps(a.v, _mm256_setzero_ps(), _CMP_GT_OQ)) != 0;
}

/// Eight RGBA pixels as read from a frame: their bytes, and the colour channels as floats (one
/// channel a `Float8`) for blending.
struct Pixels8 {
  __m256i bytes;  ///< the 32 bytes, pixel i in lane i
  Float8 r;       ///< red, 0..255, integral
  Float8 g;       ///< green, 0..255, integral
  Float8 b;       ///< blue, 0..255, integral

  /// Eight RGBA pixels from `at` (32 bytes).
  static Pixels8 load(const std::uint8_t* at) { return of_bytes(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(at))); }

  /// Four RGBA pixels from `low` (16 bytes) in lanes 0..3 and four from `high` in lanes 4..7.
  static Pixels8 load_halves(const std::uint8_t* low, const std::uint8_t* high) {
    return of_bytes(_mm256_loadu2_m128i(reinterpret_cast<const __m128i*>(high), reinterpret_cast<const __m128i*>(low)));
  }

  /// Eight RGBA pixels of `bytes` (pixel i in lane i).
  static Pixels8 of_bytes(__m256i bytes) {
    const __m256i low = _mm256_set1_epi32(0xFF);
    return Pixels8{bytes, _mm256_cvtepi32_ps(_mm256_and_si256(bytes, low)),
                   _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(bytes, 8), low)),
                   _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srli_epi32(bytes, 16), low))};
  }

  /// Stores these pixels to `at` (32 bytes) with colour channels `red`, `green`, `blue`, each
  /// converted with truncation toward zero and its low byte kept, as `static_cast<std::uint8_t>`
  /// of a float does, and alpha as it was; a pixel whose lane of `alpha` is not above 0 (or NaN)
  /// keeps its bytes.
  void store(std::uint8_t* at, Float8 red, Float8 green, Float8 blue, Float8 alpha) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(at), blended(red, green, blue, alpha));
  }

  /// `store` of lanes 0..3 to `low` (16 bytes) and of lanes 4..7 to `high`: the pixels of
  /// `load_halves`. The two must not overlap.
  void store_halves(std::uint8_t* low, std::uint8_t* high, Float8 red, Float8 green, Float8 blue, Float8 alpha) const {
    _mm256_storeu2_m128i(reinterpret_cast<__m128i*>(high), reinterpret_cast<__m128i*>(low),
                         blended(red, green, blue, alpha));
  }

  /// Writes the red, green and blue bytes of `rgb` (bytes 0, 1, 2; byte 3 unused) to the pixels
  /// at `at` (32 bytes) whose lane of `where` is above 0, alpha as it was; the others keep their
  /// bytes.
  static void paint(std::uint8_t* at, Float8 where, std::uint32_t rgb) {
    const __m256i bytes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(at));
    const __m256i colour = _mm256_or_si256(_mm256_set1_epi32(static_cast<int>(rgb & 0x00FFFFFFu)),
                                           _mm256_andnot_si256(_mm256_set1_epi32(0x00FFFFFF), bytes));
    const __m256i write = _mm256_castps_si256(_mm256_cmp_ps(where.v, _mm256_setzero_ps(), _CMP_GT_OQ));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(at), _mm256_blendv_epi8(bytes, colour, write));
  }

 private:
  // The bytes `store` writes.
  __m256i blended(Float8 red, Float8 green, Float8 blue, Float8 alpha) const {
    const __m256i low = _mm256_set1_epi32(0xFF);
    const auto channel = [&](Float8 value) { return _mm256_and_si256(_mm256_cvttps_epi32(value.v), low); };
    const __m256i colour = _mm256_or_si256(_mm256_or_si256(channel(red), _mm256_slli_epi32(channel(green), 8)),
                                           _mm256_or_si256(_mm256_slli_epi32(channel(blue), 16),
                                                           _mm256_andnot_si256(_mm256_set1_epi32(0x00FFFFFF), bytes)));
    const __m256i write = _mm256_castps_si256(_mm256_cmp_ps(alpha.v, _mm256_setzero_ps(), _CMP_GT_OQ));
    return _mm256_blendv_epi8(bytes, colour, write);
  }
};

}  // namespace impulse2d::render

#endif
