# bench_v3 (bench/v3/, docs/bench/v3.md): impulse2d beside Box2D v3 at equal vector width in one
# run (issue 33): 4 lanes against v3's SSE2 build, 8 lanes against its AVX2 build, alternated
# pairs with their ratios. Box2D v3 is never vendored: give a v3 source tree with
#   -DIMPULSE2D_BOX2D_V3_SOURCE=/path/to/box2d   (and, unless it is a git checkout,
#   -DIMPULSE2D_BOX2D_V3_COMMIT=<the 40-hex commit it was taken from>)
# and it is built here twice (ExternalProject, static, Release, no samples/tests/benchmarks,
# validation off): SSE2 (its default) and AVX2. Without it nothing of v3 is built (no network
# either) and bench_v3 only says how to configure it (exit status 2).
set(IMPULSE2D_BOX2D_V3_SOURCE "" CACHE PATH
    "a Box2D v3 source tree to build and run beside impulse2d in bench_v3 (empty: none)")
set(IMPULSE2D_BOX2D_V3_COMMIT "" CACHE STRING
    "the Box2D v3 commit of IMPULSE2D_BOX2D_V3_SOURCE (read with git when it is a checkout)")

# What does not need v3: the runner line, the pair and scale statistics, the options, the scenes by name
# (tested by tests/lab/test_bench_v3.cpp).
add_library(impulse2d_bench_v3 STATIC
  ${CMAKE_CURRENT_SOURCE_DIR}/v3/v3_options.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/v3/v3_pairs.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/v3/v3_protocol.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/v3/v3_scale.cpp)
target_link_libraries(impulse2d_bench_v3 PUBLIC impulse2d_compare_scenes)
target_include_directories(impulse2d_bench_v3 PUBLIC ${PROJECT_SOURCE_DIR})

# The driver: built always; it runs impulse2d in-process and v3 through the runners.
add_executable(bench_v3 ${CMAKE_CURRENT_SOURCE_DIR}/v3/bench_v3.cpp
                        ${CMAKE_CURRENT_SOURCE_DIR}/compare/compare_run.cpp
                        ${CMAKE_CURRENT_SOURCE_DIR}/compare/world_simulation.cpp)
target_link_libraries(bench_v3 PRIVATE impulse2d_bench_v3 impulse2d_lab)
target_include_directories(bench_v3 PRIVATE ${PROJECT_SOURCE_DIR})

if(IMPULSE2D_BOX2D_V3_SOURCE)
  get_filename_component(v3_source "${IMPULSE2D_BOX2D_V3_SOURCE}" ABSOLUTE)
  if(NOT EXISTS "${v3_source}/CMakeLists.txt" OR NOT EXISTS "${v3_source}/include/box2d/box2d.h")
    message(FATAL_ERROR "IMPULSE2D_BOX2D_V3_SOURCE=${v3_source} is not a Box2D v3 source tree "
                        "(no CMakeLists.txt and include/box2d/box2d.h)")
  endif()
  # The commit: from git when the tree is a checkout, else as given; both must agree.
  set(v3_git_commit "")
  find_package(Git QUIET)
  if(GIT_FOUND AND EXISTS "${v3_source}/.git")
    execute_process(COMMAND "${GIT_EXECUTABLE}" -C "${v3_source}" rev-parse HEAD
                    OUTPUT_VARIABLE v3_git_commit OUTPUT_STRIP_TRAILING_WHITESPACE
                    RESULT_VARIABLE v3_git_status ERROR_QUIET)
    if(NOT v3_git_status EQUAL 0)
      set(v3_git_commit "")
    endif()
  endif()
  set(v3_commit "${IMPULSE2D_BOX2D_V3_COMMIT}")
  if(v3_git_commit)
    if(v3_commit AND NOT v3_commit STREQUAL v3_git_commit)
      message(FATAL_ERROR "IMPULSE2D_BOX2D_V3_COMMIT=${v3_commit} but ${v3_source} is at ${v3_git_commit}")
    endif()
    set(v3_commit "${v3_git_commit}")
  endif()
  if(NOT v3_commit MATCHES "^[0-9a-f]+$")
    message(FATAL_ERROR "${v3_source} is not a git checkout: give the commit it was taken from "
                        "as -DIMPULSE2D_BOX2D_V3_COMMIT=<40 hex digits> (got '${v3_commit}')")
  endif()
  string(LENGTH "${v3_commit}" v3_commit_length)
  if(NOT v3_commit_length EQUAL 40)
    message(FATAL_ERROR "IMPULSE2D_BOX2D_V3_COMMIT must be the full 40-hex commit, not '${v3_commit}'")
  endif()
  message(STATUS "bench_v3: Box2D v3 ${v3_commit} from ${v3_source}")

  include(ExternalProject)
  set(v3_compilers -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER} -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER})
  foreach(width sse2 avx2)
    if(width STREQUAL "avx2")
      set(v3_avx2 ON)
    else()
      set(v3_avx2 OFF)
    endif()
    set(v3_binary ${CMAKE_BINARY_DIR}/box2d_v3/${width})
    set(v3_library ${v3_binary}/src/${CMAKE_STATIC_LIBRARY_PREFIX}box2d${CMAKE_STATIC_LIBRARY_SUFFIX})
    ExternalProject_Add(box2d_v3_${width}
      SOURCE_DIR ${v3_source}
      BINARY_DIR ${v3_binary}
      PREFIX ${CMAKE_BINARY_DIR}/box2d_v3/${width}-stamp
      CMAKE_ARGS -DCMAKE_BUILD_TYPE=Release ${v3_compilers}
                 -DBUILD_SHARED_LIBS=OFF -DBOX2D_AVX2=${v3_avx2}
                 -DBOX2D_SAMPLES=OFF -DBOX2D_BENCHMARKS=OFF -DBOX2D_UNIT_TESTS=OFF
                 -DBOX2D_DOCS=OFF -DBOX2D_VALIDATE=OFF -DBOX2D_PROFILE=OFF
                 -DBOX2D_SANITIZE=OFF -DBOX2D_DISABLE_SIMD=OFF -DBOX2D_DOUBLE_PRECISION=OFF
      BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target box2d
      INSTALL_COMMAND ""
      BUILD_BYPRODUCTS ${v3_library}
      BUILD_ALWAYS OFF)
    add_library(impulse2d_box2d_v3_${width} STATIC IMPORTED)
    set_target_properties(impulse2d_box2d_v3_${width} PROPERTIES
      IMPORTED_LOCATION ${v3_library}
      INTERFACE_INCLUDE_DIRECTORIES ${v3_source}/include
      INTERFACE_LINK_LIBRARIES m)
    add_dependencies(impulse2d_box2d_v3_${width} box2d_v3_${width})

    # The runner: one scene in this v3 build, one machine-readable line (bench/v3/v3_runner.cpp).
    add_executable(bench_v3_runner_${width} ${CMAKE_CURRENT_SOURCE_DIR}/v3/v3_runner.cpp)
    target_link_libraries(bench_v3_runner_${width} PRIVATE impulse2d_box2d_v3_${width} impulse2d_bench_v3)
    target_include_directories(bench_v3_runner_${width} PRIVATE ${PROJECT_SOURCE_DIR})
    target_compile_definitions(bench_v3_runner_${width} PRIVATE
      IMPULSE2D_V3_COMMIT="${v3_commit}" IMPULSE2D_V3_WIDTH="${width}")
    add_dependencies(bench_v3 bench_v3_runner_${width})
  endforeach()
  target_compile_definitions(bench_v3 PRIVATE
    IMPULSE2D_V3_COMMIT="${v3_commit}"
    IMPULSE2D_V3_RUNNER_SSE2="$<TARGET_FILE:bench_v3_runner_sse2>"
    IMPULSE2D_V3_RUNNER_AVX2="$<TARGET_FILE:bench_v3_runner_avx2>")
endif()
