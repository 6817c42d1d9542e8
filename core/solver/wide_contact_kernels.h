#pragma once
/// @file wide_contact_kernels.h
/// The wide contact passes, one entry point per lane count (see `wide_contact_kernel.h`):
/// 4 lanes (SSE2 on every x86-64 CPU; the compiler's generic vector code elsewhere) and, on
/// x86-64 only, 8 lanes (AVX2, chosen at run time when the CPU has it). Both give the same bits.

#include "core/solver/contact_block.h"
#include "core/solver/solver_body.h"

#include <cstddef>

namespace impulse2d {

/// One pass (soft or relax, per `pass`) over `count` 4-lane blocks, in order.
void solve_contact_blocks_4(const ContactBlockArrays<4>& blocks, SolverBody* bodies,
                            const WidePassSettings& pass);
/// Applies the blocks' accumulated impulses to their bodies (warm starting), 4 lanes.
void warm_start_contact_blocks_4(const ContactBlock<4>* blocks, std::size_t count,
                                 SolverBody* bodies);

#if defined(__x86_64__)
/// True when this CPU runs the 8-lane kernels (AVX2).
bool wide_contact_kernels_8_available();
/// One pass over `count` 8-lane blocks; only when `wide_contact_kernels_8_available()`.
void solve_contact_blocks_8(const ContactBlockArrays<8>& blocks, SolverBody* bodies,
                            const WidePassSettings& pass);
/// Warm starting over 8-lane blocks; only when `wide_contact_kernels_8_available()`.
void warm_start_contact_blocks_8(const ContactBlock<8>* blocks, std::size_t count,
                                 SolverBody* bodies);
#endif

}  // namespace impulse2d
