# Renderer suites: primitives and camera, world overlays, thread-count determinism (child
# processes), PNG output and frame writer, OSMesa against EGL.
impulse2d_add_test(test_render
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_render_primitives.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_world.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_overlays.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_determinism.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_output.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_support.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_stb_image.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_render_backends.cpp
  LIBS impulse2d_render)
target_include_directories(test_render SYSTEM PRIVATE ${STB_INCLUDE_DIR})
# stb_image is third-party code: its warnings are silenced on its one file only.
set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/test_render_stb_image.cpp
                            PROPERTIES COMPILE_OPTIONS "-w")
# The CPU rasteriser of the overlay layers: thread-count independence, exact coverage,
# clipping and agreement with llvmpipe.
impulse2d_add_test(test_render_software
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_render_software.cpp
  LIBS impulse2d_render)
