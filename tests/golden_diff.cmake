# The golden-image comparison library on synthetic images (no scenes, no renderer).
impulse2d_add_test(test_image_diff
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_image_diff.cpp
  LIBS impulse2d_golden)
