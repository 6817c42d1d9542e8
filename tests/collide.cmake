# Shapes and narrow phase: validation, mass properties, queries, every collide pair, jump table.
impulse2d_add_test(test_shape
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_shape.cpp
  LIBS impulse2d_core)
impulse2d_add_test(test_collide
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_collide.cpp
  LIBS impulse2d_core)
