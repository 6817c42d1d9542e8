// cos_sin_4 four doubles at a time, x86-64 only: core/CMakeLists.txt compiles this file alone
// with -mavx2 (no FMA: the lanes must round as `cos_sin` does). Called only after
// `cos_sin_4_avx2_available()` said yes.
#if defined(__x86_64__)

#include "core/trig_kernel.h"
#include "core/trig_kernels.h"

namespace impulse2d {

void cos_sin_4_avx2(const float* angles, CosSin* results) {
  if (all_in_vector_range(angles)) {
    cos_sin_4_lanes<4>(angles, results);
    return;
  }
  for (int lane = 0; lane < 4; ++lane) results[lane] = cos_sin(angles[lane]);
}

}  // namespace impulse2d

#endif
