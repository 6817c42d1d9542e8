# The API reference (docs/Doxyfile): doxygen over the installed libraries' headers, failing
# on any undocumented public declaration. About 2 s.
find_program(DOXYGEN_EXECUTABLE doxygen)
if(DOXYGEN_EXECUTABLE)
  add_test(NAME api_reference
           COMMAND sh -c "(cat docs/Doxyfile; echo 'OUTPUT_DIRECTORY=${PROJECT_BINARY_DIR}/api') | '${DOXYGEN_EXECUTABLE}' -"
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
else()
  message(WARNING "doxygen not found: the api_reference test is skipped (apt-get install doxygen)")
endif()
