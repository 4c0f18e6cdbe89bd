# ctest driver: the version in CITATION.cff and the generated epac/version.hpp equal
# project(epac VERSION). Inputs: VERSION, CFF, HEADER.
file(STRINGS ${CFF} line REGEX "^version: ")
if(NOT line STREQUAL "version: ${VERSION}")
  message(FATAL_ERROR "CITATION.cff says '${line}', project(epac VERSION) is ${VERSION}")
endif()
file(STRINGS ${HEADER} line REGEX "define EPAC_VERSION_STRING")
if(NOT line MATCHES "\"${VERSION}\"")
  message(FATAL_ERROR "${HEADER}: '${line}', expected ${VERSION}")
endif()
