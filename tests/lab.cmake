# The speed-accuracy lab: scenario files and their exact answers, CSV and chart layout, the
# stability map's measured boundaries pinned from both sides, tune's answer within its bound,
# and `impulse2d lab` / `lab merge` / `tune` run as subprocesses (a --quick subset).
impulse2d_add_test(test_lab
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_lab_scenarios.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_lab_results.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_lab_boundaries.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/test_lab_tune.cpp
  LIBS impulse2d_lab)
impulse2d_add_test(test_lab_cli
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/test_lab_cli.cpp
  LIBS impulse2d_lab)
target_compile_definitions(test_lab_cli PRIVATE IMPULSE2D_CLI="$<TARGET_FILE:impulse2d>")
add_dependencies(test_lab_cli impulse2d)
# The whole lab in its --quick form (every scenario, a smaller method space, 2 repeats, the
# short stability map, charts): under a minute on two cores.
add_test(NAME lab_quick
         COMMAND impulse2d lab --quick --out ${CMAKE_BINARY_DIR}/lab_quick)
set_tests_properties(lab_quick PROPERTIES TIMEOUT 300)
