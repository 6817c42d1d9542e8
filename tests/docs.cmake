# The docs (tests/check_docs.sh): the commands of every sh block of README.md and docs/*.md run
# as written, in order, in a scratch directory per page (the slow ones, listed in the script
# with their reasons, with --dry-run only; build, install and package lines not at all); every
# local link and image resolves; the README is at most 250 lines and its table of contents
# lists every section. Under a minute.
add_test(NAME docs_commands_and_links
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_docs.sh $<TARGET_FILE:impulse2d>
                 ${PROJECT_SOURCE_DIR})
