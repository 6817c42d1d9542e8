/// @file test_golden_support.cpp
#include "tests/golden/test_golden_support.h"

#include <stdexcept>

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

CheckOutcome check_golden_variant(const std::string& golden, const SceneVariant& change) {
  const GoldenSpec* spec = find_golden(golden);
  if (spec == nullptr) throw std::logic_error("no golden " + golden);
  CheckSettings settings = suite_settings();
  settings.update_mode = UpdateMode::None;
  settings.artifact_root.clear();
  return run_golden_check(spec->id(), spec->scene, static_cast<int>(spec->step),
                          scene_frame_producer(*spec, change), settings);
}

bool passes_on_this_renderer(const CheckOutcome& outcome) {
  return !outcome.golden_written && (outcome.failure_class == FailureClass::None ||
                                     outcome.failure_class == FailureClass::NoRendererBaseline);
}

}  // namespace impulse2d::golden::testing
