# cmake -DMODE=installed|subdirectory -DSOURCE_DIR=<impulse2d> -DBUILD_DIR=<its build>
#       -DWORK_DIR=<scratch> -DGENERATOR=<cmake generator> -DCXX=<compiler> -P run_consumer.cmake
# The consumer project (this folder) built as an outside project would build it, then run:
#   installed     `cmake --install BUILD_DIR --prefix WORK_DIR/prefix`, the consumer configured
#                 with find_package(impulse2d CONFIG) and -ffast-math in its own flags (the
#                 core's usage requirements must switch it off again), then main.cpp compiled
#                 by hand with `pkg-config --cflags --libs impulse2d`; both must print the
#                 same state hash;
#   subdirectory  the consumer adds SOURCE_DIR with add_subdirectory while GoogleTest and
#                 CLI11 are hidden (CMAKE_DISABLE_FIND_PACKAGE_*): neither is needed.
# Any failing step stops the test with the step's output.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}): ${what} failed (${status}):\n${out}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

function(expect_ok what)
  if(NOT last_output MATCHES "consumer: ok")
    message(FATAL_ERROR "consumer (${MODE}): ${what} did not say ok:\n${last_output}")
  endif()
  message(STATUS "${what}: ${last_output}")
endfunction()

set(consumer_source ${CMAKE_CURRENT_LIST_DIR})
set(work ${WORK_DIR}/${MODE})
file(REMOVE_RECURSE ${work})
set(configure ${CMAKE_COMMAND} -G ${GENERATOR} -S ${consumer_source} -B ${work}/build
              -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX})

if(MODE STREQUAL "installed")
  set(prefix ${work}/prefix)
  run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  foreach(file include/impulse2d/core/world.h include/impulse2d/scene/scene_loader.h
               lib/cmake/impulse2d/impulse2dConfig.cmake
               lib/cmake/impulse2d/impulse2dConfigVersion.cmake lib/pkgconfig/impulse2d.pc)
    if(NOT EXISTS ${prefix}/${file})
      message(FATAL_ERROR "consumer (installed): ${prefix}/${file} was not installed")
    endif()
  endforeach()
  if(EXISTS ${prefix}/include/impulse2d/tests OR EXISTS ${prefix}/include/tests)
    message(FATAL_ERROR "consumer (installed): test headers were installed under ${prefix}/include")
  endif()
  run("configure with find_package" ${configure} -DCMAKE_PREFIX_PATH=${prefix}
      -DCMAKE_CXX_FLAGS=-ffast-math)
  run("build" ${CMAKE_COMMAND} --build ${work}/build)
  run("run" ${work}/build/consumer)
  expect_ok("find_package consumer")
  set(cmake_output "${last_output}")

  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  run("pkg-config" pkg-config --cflags --libs impulse2d)
  string(STRIP "${last_output}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  run("compile with pkg-config flags" ${CXX} ${consumer_source}/main.cpp -o ${work}/consumer_pc
      ${flags})
  run("run" ${work}/consumer_pc)
  expect_ok("pkg-config consumer")
  # Same source, two build systems, one of them asking for -ffast-math: the same state.
  string(REGEX MATCH "state hash [0-9a-f]+" cmake_hash "${cmake_output}")
  string(REGEX MATCH "state hash [0-9a-f]+" pc_hash "${last_output}")
  if(NOT cmake_hash STREQUAL pc_hash)
    message(FATAL_ERROR "consumer (installed): ${cmake_hash} with CMake and -ffast-math, "
                        "${pc_hash} with pkg-config: the usage requirements did not hold")
  endif()
elseif(MODE STREQUAL "subdirectory")
  run("configure with add_subdirectory" ${configure} -DIMPULSE2D_SOURCE_DIR=${SOURCE_DIR}
      -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON)
  run("build" ${CMAKE_COMMAND} --build ${work}/build --parallel 2)
  run("run" ${work}/build/consumer)
  expect_ok("add_subdirectory consumer")
else()
  message(FATAL_ERROR "run_consumer.cmake: MODE must be installed or subdirectory, not '${MODE}'")
endif()
