# The installed package: impulse2dConfig.cmake + version file with the exported targets
# (find_package(impulse2d CONFIG)), and impulse2d.pc for pkg-config. Included by the top-level
# CMakeLists.txt after the libraries are defined.
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set(IMPULSE2D_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/impulse2d)
install(EXPORT impulse2dTargets NAMESPACE impulse2d:: DESTINATION ${IMPULSE2D_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/impulse2dConfig.cmake.in
  ${PROJECT_BINARY_DIR}/impulse2dConfig.cmake INSTALL_DESTINATION ${IMPULSE2D_CMAKE_DIR})
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/impulse2dConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/impulse2dConfig.cmake
              ${PROJECT_BINARY_DIR}/impulse2dConfigVersion.cmake
        DESTINATION ${IMPULSE2D_CMAKE_DIR})

# pkg-config: one module for the libraries built (static, so their dependencies are public).
if(IMPULSE2D_BUILD_RENDER)
  set(IMPULSE2D_PC_LIBS "-limpulse2d_render -limpulse2d_image -limpulse2d_scene -limpulse2d_gameplay -limpulse2d_core")
  if(IMPULSE2D_OSMESA)
    set(IMPULSE2D_PC_REQUIRES "glm nlohmann_json osmesa egl libdeflate")
  else()
    set(IMPULSE2D_PC_REQUIRES "glm nlohmann_json opengl egl libdeflate")
  endif()
else()
  set(IMPULSE2D_PC_LIBS "-limpulse2d_scene -limpulse2d_gameplay -limpulse2d_core")
  set(IMPULSE2D_PC_REQUIRES "glm nlohmann_json")
endif()
# Relocatable: the prefix is found from the .pc file's own folder, so `cmake --install
# --prefix P` works whatever CMAKE_INSTALL_PREFIX was at configure time.
file(RELATIVE_PATH IMPULSE2D_PC_PREFIX_FROM_PC_DIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" IMPULSE2D_PC_PREFIX_FROM_PC_DIR "${IMPULSE2D_PC_PREFIX_FROM_PC_DIR}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/impulse2d.pc.in ${PROJECT_BINARY_DIR}/impulse2d.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/impulse2d.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
