# The polygon radius cached in each made polygon (used by contact recycling and speculative reach).
impulse2d_add_test(test_polygon_radius
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_polygon_radius.cpp
  LIBS impulse2d_core)
