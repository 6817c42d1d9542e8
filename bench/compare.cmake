# bench_compare's scenes and stability figures as a library of their own (impulse2d_compare_scenes:
# core only, no lab, no peer), so that a program linking another engine (bench/v3.cmake's Box2D v3
# runners) builds the very bodies bench_compare steps and judges them alike.
add_library(impulse2d_compare_scenes STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_scene.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/stability.cpp)
target_link_libraries(impulse2d_compare_scenes PUBLIC impulse2d_core)
target_include_directories(impulse2d_compare_scenes PUBLIC ${PROJECT_SOURCE_DIR})
# bench_compare (bench/compare/): impulse2d against Box2D 2.4.1 and Chipmunk 7 on the same scenes
# in the same run, with stability beside every speed and a scaling chart (README "Peers in
# one run"). Uses the lab's peers (impulse2d_lab, lab/).
add_executable(bench_compare
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/bench_compare.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_chart.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_report.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_run.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_scale.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/compare/world_simulation.cpp)
target_link_libraries(bench_compare PRIVATE impulse2d_compare_scenes impulse2d_lab)
target_include_directories(bench_compare PRIVATE ${PROJECT_SOURCE_DIR})
