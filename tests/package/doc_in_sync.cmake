# ctest driver: a document shows a source file verbatim between
#   <!-- begin NAME -->  and  <!-- end NAME -->
# in a ```cpp block (docs/install.md shows tests/package/consumer/host_loop.cpp); this fails when
# the two differ, so the document cannot drift from the program CI compiles and runs.
# Inputs: DOC (the markdown file), FILE (the source), NAME (the path as the markers write it).
file(READ ${DOC} doc)
file(READ ${FILE} program)
set(begin "<!-- begin ${NAME} -->\n```cpp\n")
set(end "```\n<!-- end ${NAME} -->")
string(FIND "${doc}" "${begin}" b)
string(FIND "${doc}" "${end}" e)
if(b EQUAL -1 OR e EQUAL -1)
  message(FATAL_ERROR "${DOC} has no block for ${NAME} (markers '<!-- begin ${NAME} -->' / '<!-- end ${NAME} -->')")
endif()
string(LENGTH "${begin}" lb)
math(EXPR start "${b} + ${lb}")
math(EXPR len "${e} - ${start}")
string(SUBSTRING "${doc}" ${start} ${len} shown)
if(NOT shown STREQUAL program)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/doc_shown.cpp "${shown}")
  message(FATAL_ERROR "the copy of ${NAME} in ${DOC} differs from the file; see: diff ${FILE} "
                      "${CMAKE_CURRENT_BINARY_DIR}/doc_shown.cpp (update the block in ${DOC})")
endif()
