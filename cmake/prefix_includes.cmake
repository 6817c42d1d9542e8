# cmake -DSOURCE_DIR=<folder> -DOUTPUT_DIR=<dir> -P prefix_includes.cmake
# Copies every header of SOURCE_DIR into OUTPUT_DIR, turning the project's own includes
# ("core/world.h", "gameplay/...", "scene/...", "render/...") into "impulse2d/core/world.h" so
# that the copies resolve against the consumers' include tree. Called by impulse2d_library().
file(GLOB headers ${SOURCE_DIR}/*.h)
file(MAKE_DIRECTORY ${OUTPUT_DIR})
# A header removed or renamed in the source folder leaves no stale copy behind.
file(GLOB staged ${OUTPUT_DIR}/*.h)
foreach(copy ${staged})
  get_filename_component(name ${copy} NAME)
  if(NOT EXISTS ${SOURCE_DIR}/${name})
    file(REMOVE ${copy})
  endif()
endforeach()
foreach(header ${headers})
  get_filename_component(name ${header} NAME)
  file(READ ${header} text)
  string(REGEX REPLACE "#include \"(core|gameplay|scene|render)/" "#include \"impulse2d/\\1/"
         text "${text}")
  file(WRITE ${OUTPUT_DIR}/${name} "${text}")
endforeach()
