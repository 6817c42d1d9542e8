# The golden-image suite: one test per golden of the built-in scenes, the golden inventory
# (unused or unpaired files), sensitivity to small physics changes (behaviour changed),
# rounding changes classed as numerical noise, cross-process nondeterminism, insensitivity to
# the rasteriser's thread count (child processes), PNG metadata. Goldens live in
# golden_images/; failures leave their artifacts and index.html in GOLDEN_ARTIFACT_DIR
# (default: <build>/golden_artifacts).
if(TARGET impulse2d_golden_scenes)
  impulse2d_add_test(test_golden
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_scenes.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_inventory.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_sensitivity.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_noise.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_threads.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_child.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_processes.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_metadata.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_support.cpp
            ${CMAKE_CURRENT_SOURCE_DIR}/test_render_support.cpp
    LIBS impulse2d_golden_scenes)
  target_compile_definitions(test_golden PRIVATE
    IMPULSE2D_GOLDEN_DIR="${PROJECT_SOURCE_DIR}/golden_images"
    IMPULSE2D_GOLDEN_ARTIFACT_DIR="${PROJECT_BINARY_DIR}/golden_artifacts")
endif()

# The check runner on synthetic frame producers and the `impulse2d diff` command: no
# renderer, no scenes.
impulse2d_add_test(test_golden_harness
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_check_run.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_diff_command.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_noise_envelope.cpp
  LIBS impulse2d_golden)

# `impulse2d golden` as a user's CI runs it, on copies of examples/golden_project.
impulse2d_add_test(test_golden_command
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_golden_command.cpp
  LIBS impulse2d_golden)
target_compile_definitions(test_golden_command PRIVATE
  IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>"
  IMPULSE2D_EXAMPLE_PROJECT="${PROJECT_SOURCE_DIR}/examples/golden_project")
add_dependencies(test_golden_command impulse2d)

# The example project checked exactly as its README's CI job does.
file(GLOB example_scenes CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/golden_project/scenes/*.json)
add_test(NAME ExampleProjectGoldens
         COMMAND impulse2d golden check ${example_scenes} --repeat 2
                 --report ${PROJECT_BINARY_DIR}/example_golden_report
                 --junit ${PROJECT_BINARY_DIR}/example_golden_report.xml
         WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}/examples/golden_project)
