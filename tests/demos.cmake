# Demos: scene registry, built-in scenes, JSON scene files, frames, trace (in-process), and the
# impulse2d command line run as a subprocess (bad input, exit codes, no partial files).
impulse2d_add_test(test_demos
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_demos_scenes.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_demos_scene_files.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_demos_divergence.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_demos_force_event.cpp
  LIBS impulse2d_demos)
target_compile_definitions(test_demos PRIVATE IMPULSE2D_SCENES_DIR="${PROJECT_SOURCE_DIR}/demos/scenes")
impulse2d_add_test(test_cli
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cli.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_conventions.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_frames.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_sheet.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_units.cpp
  LIBS impulse2d_demos impulse2d_golden)
target_compile_definitions(test_cli PRIVATE IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>")
add_dependencies(test_cli impulse2d)
# The browser viewer of `render --html`: its page and data, and the page in headless Chromium
# (skipped without it) against golden_images/viewer/ (failures leave their pictures in
# GOLDEN_ARTIFACT_DIR, default <build>/golden_artifacts).
impulse2d_add_test(test_cli_html
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_html.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/headless_chromium.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/screenshot_golden.cpp
  LIBS impulse2d_demos impulse2d_golden)
target_compile_definitions(test_cli_html PRIVATE
  IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>"
  IMPULSE2D_GOLDEN_DIR="${PROJECT_SOURCE_DIR}/golden_images"
  IMPULSE2D_GOLDEN_ARTIFACT_DIR="${PROJECT_BINARY_DIR}/golden_artifacts")
add_dependencies(test_cli_html impulse2d)
# The view options (HUD, legend, scales, camera, highlight) of `render` and `sheet`.
impulse2d_add_test(test_cli_view
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cli_view.cpp
  LIBS impulse2d_demos)
target_compile_definitions(test_cli_view PRIVATE IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>")
add_dependencies(test_cli_view impulse2d)
# The bad-input catalogue: a table of broken scene files and command lines (data in
# tests/bad_inputs/catalogue.json), one ctest test per case.
impulse2d_add_test(test_bad_input_catalogue
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_bad_input_catalogue.cpp
  LIBS impulse2d_demos)
target_compile_definitions(test_bad_input_catalogue PRIVATE
  IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>"
  IMPULSE2D_CATALOGUE="${CMAKE_CURRENT_SOURCE_DIR}/bad_inputs/catalogue.json")
add_dependencies(test_bad_input_catalogue impulse2d)
# Determinism across compilers: pinned final state hashes of long runs (checked in the GCC
# build and in scripts/test.sh's Clang build).
impulse2d_add_test(test_cross_build_hash
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_cross_build_hash.cpp
  LIBS impulse2d_demos)
