// The 8-lane contact passes, x86-64 only: core/CMakeLists.txt compiles this file alone with
// -mavx2 (no FMA: the lanes must round as the 4-lane kernels do). Called only after
// `wide_contact_kernels_8_available()` said yes.
#if defined(__x86_64__)

#include "core/solver/wide_contact_kernel.h"
#include "core/solver/wide_contact_kernels.h"

namespace impulse2d {

bool wide_contact_kernels_8_available() { return __builtin_cpu_supports("avx2"); }

void solve_contact_blocks_8(const ContactBlockArrays<8>& blocks, SolverBody* bodies,
                            const WidePassSettings& pass) {
  solve_blocks<8>(blocks, bodies, pass);
}

void warm_start_contact_blocks_8(const ContactBlock<8>* blocks, std::size_t count,
                                 SolverBody* bodies) {
  warm_start_blocks<8>(blocks, count, bodies);
}

}  // namespace impulse2d

#endif
