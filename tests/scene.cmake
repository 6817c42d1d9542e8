# The scene library on its own (no renderer linked): frame selections, and a level file loaded
# and stepped by a binary that has no GL library in it.
impulse2d_add_test(test_scene
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_frame_selection.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_scene_headless.cpp
  LIBS impulse2d_scene)
target_compile_definitions(test_scene PRIVATE IMPULSE2D_SCENES_DIR="${PROJECT_SOURCE_DIR}/demos/scenes")
