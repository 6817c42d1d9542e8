# The multi-threaded step (issue 33): ms per step and speed-up at several worker counts on the
# large pyramid and many pyramids (bench_compare's scene builders, impulse2d only).
add_executable(bench_workers ${CMAKE_CURRENT_SOURCE_DIR}/workers_bench.cpp
                             ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_scene.cpp)
target_link_libraries(bench_workers PRIVATE impulse2d_core)
target_include_directories(bench_workers PRIVATE ${PROJECT_SOURCE_DIR})
