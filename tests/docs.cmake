# The docs (tests/check_docs.sh): every impulse2d command in the README's sh blocks passes
# `impulse2d --dry-run`, every local link and image in README.md and docs/*.md resolves, and
# the README's table of contents lists every section. About 1 s.
add_test(NAME docs_commands_and_links
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/check_docs.sh $<TARGET_FILE:impulse2d>
                 ${PROJECT_SOURCE_DIR})
