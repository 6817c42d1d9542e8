// The 4-lane contact passes, compiled for the build's baseline instruction set (SSE2 on x86-64).
#include "core/solver/wide_contact_kernel.h"
#include "core/solver/wide_contact_kernels.h"

namespace impulse2d {

void solve_contact_blocks_4(const ContactBlockArrays<4>& blocks, SolverBody* bodies,
                            const WidePassSettings& pass) {
  solve_blocks<4>(blocks, bodies, pass);
}

void warm_start_contact_blocks_4(const ContactBlock<4>* blocks, std::size_t count,
                                 SolverBody* bodies) {
  warm_start_blocks<4>(blocks, count, bodies);
}

}  // namespace impulse2d
