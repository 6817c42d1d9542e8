# The speed-accuracy lab (`impulse2d lab`, `impulse2d tune`): scenarios with exact answers
# (bench/lab/scenarios/*.json), method sweeps, peers, charts, the stability map. Library
# impulse2d_lab, used by the impulse2d command line and the lab's tests.
file(GLOB lab_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/lab/*.cpp)
list(FILTER lab_sources EXCLUDE REGEX "peer_(box2d|chipmunk)\\.cpp$")
add_library(impulse2d_lab STATIC ${lab_sources})
target_link_libraries(impulse2d_lab PUBLIC impulse2d_demos impulse2d_render)
target_compile_definitions(impulse2d_lab PRIVATE IMPULSE2D_LAB_DIR="${CMAKE_CURRENT_SOURCE_DIR}/lab")

# Peers, each compiled in only when its Debian package is installed (scripts/setup.sh does).
find_package(box2d CONFIG QUIET)
if(box2d_FOUND)
  target_sources(impulse2d_lab PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/lab/peer_box2d.cpp)
  target_link_libraries(impulse2d_lab PRIVATE box2d::box2d)
  target_compile_definitions(impulse2d_lab PRIVATE IMPULSE2D_HAVE_BOX2D)
else()
  message(STATUS "lab: libbox2d-dev not found, the Box2D peer is skipped")
endif()
find_path(CHIPMUNK_INCLUDE_DIR chipmunk/chipmunk.h)
find_library(CHIPMUNK_LIBRARY chipmunk)
if(CHIPMUNK_INCLUDE_DIR AND CHIPMUNK_LIBRARY)
  target_sources(impulse2d_lab PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/lab/peer_chipmunk.cpp)
  target_include_directories(impulse2d_lab PRIVATE ${CHIPMUNK_INCLUDE_DIR})
  target_link_libraries(impulse2d_lab PRIVATE ${CHIPMUNK_LIBRARY} m)
  target_compile_definitions(impulse2d_lab PRIVATE IMPULSE2D_HAVE_CHIPMUNK)
else()
  message(STATUS "lab: libchipmunk-dev not found, the Chipmunk peer is skipped")
endif()

target_link_libraries(impulse2d PRIVATE impulse2d_lab)
