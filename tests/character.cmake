# Platformer character: jumps (apex, coyote, buffer, extra and wall jumps) and ground (slopes,
# one-way and moving platforms, traction, input scripts, determinism).
impulse2d_add_test(test_character
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_character_jump.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_character_ground.cpp
  LIBS impulse2d_gameplay)
# The platformer demo's scripted run, checkpoint by checkpoint.
impulse2d_add_test(test_character_scene
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_character_scene.cpp
  LIBS impulse2d_demos)
