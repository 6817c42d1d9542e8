# impulse2d as a library: tests/consumer/ (a few lines of CMake and C++) built as an outside
# project against the installed tree (find_package, then pkg-config) and against the source
# tree (add_subdirectory, with GoogleTest hidden). Not in the sanitizer/fuzzer build: its
# instrumented libraries would need the same flags in the consumer, and it checks packaging,
# not code.
if(NOT IMPULSE2D_SANITIZE AND NOT IMPULSE2D_FUZZ)
  foreach(mode installed subdirectory)
    add_test(NAME consumer_${mode}
             COMMAND ${CMAKE_COMMAND} -DMODE=${mode} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
                     -DBUILD_DIR=${PROJECT_BINARY_DIR} -DWORK_DIR=${PROJECT_BINARY_DIR}/consumer
                     -DGENERATOR=${CMAKE_GENERATOR} -DCXX=${CMAKE_CXX_COMPILER}
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer.cmake)
  endforeach()
  # The add_subdirectory build compiles the four libraries again (about 3 minutes on 2 cores).
  set_tests_properties(consumer_installed PROPERTIES TIMEOUT 300)
  set_tests_properties(consumer_subdirectory PROPERTIES TIMEOUT 900)
endif()
