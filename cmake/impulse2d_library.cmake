# impulse2d_library(<target> <export-name> HEADERS <header>...): makes one of the installed
# libraries (core, gameplay, scene, render) consumable. Only the listed headers (paths relative
# to the library's folder) are public; everything else in the folder is internal and is neither
# staged nor installed. Sources include each other as "core/world.h" from the repository root;
# consumers write <impulse2d/core/world.h>. The public headers are copied at build time into
# <build>/include/impulse2d/<folder>/ with the project's own includes given the same prefix
# (prefix_includes.cmake), and that tree is what consumers see, from the build tree
# (add_subdirectory) and from the install tree alike. The repository root stays private to the
# project's own targets, so no consumer can include an internal header, tests/ or app/.
include(GNUInstallDirs)

set(IMPULSE2D_STAGED_INCLUDE_DIR ${PROJECT_BINARY_DIR}/include)

function(impulse2d_library target export_name)
  cmake_parse_arguments(ARG "" "" "HEADERS" ${ARGN})
  set(folder ${CMAKE_CURRENT_SOURCE_DIR})
  get_filename_component(folder_name ${folder} NAME)
  set(staged_dir ${IMPULSE2D_STAGED_INCLUDE_DIR}/impulse2d/${folder_name})
  set(sources)
  set(staged)
  foreach(header ${ARG_HEADERS})
    list(APPEND sources ${folder}/${header})
    list(APPEND staged ${staged_dir}/${header})
  endforeach()
  add_custom_command(
    OUTPUT ${staged}
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${folder} -DOUTPUT_DIR=${staged_dir}
            "-DHEADERS=${ARG_HEADERS}" -P ${PROJECT_SOURCE_DIR}/cmake/prefix_includes.cmake
    DEPENDS ${sources} ${PROJECT_SOURCE_DIR}/cmake/prefix_includes.cmake
    COMMENT "impulse2d: staging the public headers of ${folder_name}/ under include/impulse2d/"
    VERBATIM)
  add_custom_target(${target}_headers DEPENDS ${staged})
  add_dependencies(${target} ${target}_headers)
  set_property(TARGET ${target} PROPERTY IMPULSE2D_PUBLIC_HEADERS ${ARG_HEADERS})

  add_library(impulse2d::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${IMPULSE2D_STAGED_INCLUDE_DIR}>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${PROJECT_SOURCE_DIR})
  install(TARGETS ${target} EXPORT impulse2dTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${staged_dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impulse2d)
endfunction()
