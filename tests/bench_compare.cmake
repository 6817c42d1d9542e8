# bench_compare --smoke: tiny scenes, a few steps, every engine compiled in, tables, CSV and
# chart written. It proves the command runs; its timings are not checked.
if(TARGET bench_compare)
  add_test(NAME bench_compare_smoke
           COMMAND bench_compare --smoke --out ${CMAKE_BINARY_DIR}/bench_compare_smoke)
  set_tests_properties(bench_compare_smoke PROPERTIES TIMEOUT 120)
endif()
