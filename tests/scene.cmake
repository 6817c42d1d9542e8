# The scene library on its own (no renderer): frame selections.
impulse2d_add_test(test_scene
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_frame_selection.cpp
  LIBS impulse2d_scene)
