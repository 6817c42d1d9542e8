# cmake -DSOURCE_DIR=<folder> -DOUTPUT_DIR=<dir> -DHEADERS=<a.h;sub/b.h> -P prefix_includes.cmake
# Copies the listed public headers of SOURCE_DIR into OUTPUT_DIR (keeping their sub-folders),
# turning the project's own includes ("core/world.h", "gameplay/...", "scene/...",
# "image/...", "render/...") into "impulse2d/core/world.h" so that the copies resolve against the
# consumers' include tree. Called by impulse2d_library().
cmake_minimum_required(VERSION 3.20)
file(MAKE_DIRECTORY ${OUTPUT_DIR})
file(GLOB_RECURSE staged RELATIVE ${OUTPUT_DIR} ${OUTPUT_DIR}/*.h)
# A header removed from the list leaves no stale copy behind, nor an emptied sub-folder.
foreach(name ${staged})
  if(NOT name IN_LIST HEADERS)
    file(REMOVE ${OUTPUT_DIR}/${name})
  endif()
endforeach()
file(GLOB_RECURSE folders LIST_DIRECTORIES true ${OUTPUT_DIR}/*)
foreach(folder ${folders})
  if(IS_DIRECTORY ${folder})
    file(GLOB_RECURSE inside ${folder}/*)
    if(NOT inside)
      file(REMOVE_RECURSE ${folder})
    endif()
  endif()
endforeach()
foreach(name ${HEADERS})
  file(READ ${SOURCE_DIR}/${name} text)
  string(REGEX REPLACE "#include \"(core|gameplay|scene|image|render)/" "#include \"impulse2d/\\1/"
         text "${text}")
  file(WRITE ${OUTPUT_DIR}/${name} "${text}")
endforeach()
