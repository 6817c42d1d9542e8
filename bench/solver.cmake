# Speed against accuracy of every solver method on the 20-row pyramid.
add_executable(bench_solver ${CMAKE_CURRENT_SOURCE_DIR}/solver_bench.cpp)
target_link_libraries(bench_solver PRIVATE impulse2d_core)
target_include_directories(bench_solver PRIVATE ${PROJECT_SOURCE_DIR})
