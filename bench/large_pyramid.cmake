# Box2D v3's large_pyramid benchmark scene: does it stand after 500 steps, and at what cost.
add_executable(bench_large_pyramid ${CMAKE_CURRENT_SOURCE_DIR}/large_pyramid_bench.cpp)
target_link_libraries(bench_large_pyramid PRIVATE impulse2d_core)
target_include_directories(bench_large_pyramid PRIVATE ${PROJECT_SOURCE_DIR})
