#pragma once
/// @file trig_kernels.h
/// The paths of `cos_sin_4` (core/trig.h; internal), which picks one at run time: two doubles
/// at a time (SSE2 on every x86-64 CPU; the compiler's generic vector code elsewhere) and, on
/// x86-64 only, four (AVX2, when the CPU has it). All give the bits four `cos_sin` calls give.

#include "core/trig.h"

namespace impulse2d {

/// `cos_sin_4` two doubles at a time, for any CPU.
void cos_sin_4_two_lanes(const float* angles, CosSin* results);

#if defined(__x86_64__)
/// True when this CPU runs `cos_sin_4_avx2`. Defined in trig.cpp, which is compiled for the
/// baseline instruction set, so it runs on any x86-64 CPU.
bool cos_sin_4_avx2_available();
/// `cos_sin_4` four doubles at a time (AVX2); only when `cos_sin_4_avx2_available()`.
void cos_sin_4_avx2(const float* angles, CosSin* results);
#endif

}  // namespace impulse2d
