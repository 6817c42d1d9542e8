# Renderer speed: render, PNG encode (stb default vs libdeflate fast path) and end-to-end
# simulate+render+encode+write frames/s for 1000 bodies at 800x600 with every overlay on;
# with --ratio, ball_pit's every-overlay / shapes-only CPU ratio (the frames library renders it
# as the program does).
add_executable(bench_render ${CMAKE_CURRENT_SOURCE_DIR}/render_bench.cpp)
target_link_libraries(bench_render PRIVATE impulse2d_frames impulse2d_demos impulse2d_render Threads::Threads)
target_include_directories(bench_render PRIVATE ${PROJECT_SOURCE_DIR})
# The README's example frame (docs/overlays.png): a small scene with every overlay.
add_executable(render_example ${CMAKE_CURRENT_SOURCE_DIR}/render_example.cpp)
target_link_libraries(render_example PRIVATE impulse2d_render)
target_include_directories(render_example PRIVATE ${PROJECT_SOURCE_DIR})
