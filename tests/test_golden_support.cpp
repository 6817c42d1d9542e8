/// @file test_golden_support.cpp
#include "tests/test_golden_support.h"

#ifndef IMPULSE2D_GOLDEN_DIR
#error "IMPULSE2D_GOLDEN_DIR must name golden_images/ of the source tree (tests/golden.cmake)"
#endif
#ifndef IMPULSE2D_GOLDEN_ARTIFACT_DIR
#error "IMPULSE2D_GOLDEN_ARTIFACT_DIR must name the default artifact root (tests/golden.cmake)"
#endif

namespace impulse2d::golden::testing {

std::filesystem::path golden_dir() { return suite_settings().golden_dir; }

CheckSettings suite_settings() {
  return check_settings_from_environment(IMPULSE2D_GOLDEN_DIR, IMPULSE2D_GOLDEN_ARTIFACT_DIR);
}

}  // namespace impulse2d::golden::testing
