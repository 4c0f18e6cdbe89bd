# ctest driver: configure and build tests/package/subdir_host (add_subdirectory(epac)), run its
# program and check the version it prints. Inputs: HOST_SOURCE, EPAC_SOURCE, WORK_DIR, KOKKOS_ROOT,
# VERSION.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${HOST_SOURCE} -B ${WORK_DIR} -DEPAC_SOURCE=${EPAC_SOURCE}
                        "-DKokkos_ROOT=${KOKKOS_ROOT}" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "host configure with add_subdirectory(epac) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR} --target version_check RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "host build failed")
endif()
execute_process(COMMAND ${WORK_DIR}/version_check RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "version_check: ${out}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "^epac ${VERSION} \\(Kokkos [0-9]+\\.[0-9]+\\.[0-9]+: ")
  message(FATAL_ERROR "version_check printed '${out}' (exit ${rc}), expected epac ${VERSION}")
endif()
