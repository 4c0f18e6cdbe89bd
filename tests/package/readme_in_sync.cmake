# ctest driver: the README shows tests/package/consumer/host_loop.cpp verbatim between
#   <!-- begin tests/package/consumer/host_loop.cpp -->  and  <!-- end tests/package/consumer/host_loop.cpp -->
# in a ```cpp block; this fails when the two differ, so the README cannot drift from the program
# CI compiles and runs. Inputs: README, FILE, NAME (the path as the markers write it).
file(READ ${README} readme)
file(READ ${FILE} program)
set(begin "<!-- begin ${NAME} -->\n```cpp\n")
set(end "```\n<!-- end ${NAME} -->")
string(FIND "${readme}" "${begin}" b)
string(FIND "${readme}" "${end}" e)
if(b EQUAL -1 OR e EQUAL -1)
  message(FATAL_ERROR "README has no block for ${NAME} (markers '<!-- begin ${NAME} -->' / '<!-- end ${NAME} -->')")
endif()
string(LENGTH "${begin}" lb)
math(EXPR start "${b} + ${lb}")
math(EXPR len "${e} - ${start}")
string(SUBSTRING "${readme}" ${start} ${len} shown)
if(NOT shown STREQUAL program)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/readme_shown.cpp "${shown}")
  message(FATAL_ERROR "the README's copy of ${NAME} differs from the file; see: diff ${FILE} "
                      "${CMAKE_CURRENT_BINARY_DIR}/readme_shown.cpp (update the README block)")
endif()
