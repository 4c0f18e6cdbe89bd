# ctest driver: install epac into one prefix, move the prefix, check that no installed file names
# the build tree, the source tree, the first prefix or Kokkos's prefix, then configure, build and
# run a consumer project (tests/package/consumer) that finds the moved epac with find_package and
# Kokkos through Kokkos_ROOT. Inputs: BUILD_DIR, SOURCE_DIR (the consumer), PROJECT_SOURCE,
# WORK_DIR, KOKKOS_ROOT (Kokkos's install prefix).
file(REMOVE_RECURSE ${WORK_DIR})
set(first ${WORK_DIR}/prefix-installed)
set(moved ${WORK_DIR}/prefix-moved)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${first} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
file(RENAME ${first} ${moved})

# No absolute path of this machine in any installed file (text or binary: file(STRINGS) reads both).
file(GLOB_RECURSE installed LIST_DIRECTORIES false ${moved}/*)
list(LENGTH installed n_installed)
foreach(f ${installed})
  foreach(path ${BUILD_DIR} ${PROJECT_SOURCE} ${first} ${KOKKOS_ROOT})
    string(REGEX REPLACE "([][+.*()^$?|{}\\])" "\\\\\\1" literal "${path}")  # the path as a literal regex
    file(STRINGS ${f} hits REGEX "${literal}")
    if(hits)
      message(FATAL_ERROR "installed file ${f} names ${path}: ${hits}")
    endif()
  endforeach()
endforeach()
message(STATUS "${n_installed} installed files, none names ${BUILD_DIR}, ${PROJECT_SOURCE} or ${KOKKOS_ROOT}")
foreach(f include/epac/version.hpp lib/cmake/epac/epacConfig.cmake lib/cmake/epac/epacConfigVersion.cmake
          share/doc/epac/LICENSE share/doc/epac/CITATION.cff)
  if(NOT EXISTS ${moved}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

# The consumer: epac from the moved prefix, Kokkos from Kokkos_ROOT (no Kokkos_DIR, no hints).
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build
  "-DCMAKE_PREFIX_PATH=${moved}" "-DKokkos_ROOT=${KOKKOS_ROOT}" -DCMAKE_BUILD_TYPE=Release
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "consumer configure failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "consumer build failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/host_loop RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "host_loop: ${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "consumer run failed")
endif()

# The installed tools run from the moved prefix; they find a shared Kokkos through the loader
# (LD_LIBRARY_PATH here; ld.so.conf or the same prefix on a user's machine).
if(EXISTS ${moved}/bin/epac-run)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${KOKKOS_ROOT}/lib:${KOKKOS_ROOT}/lib64"
                          ${moved}/bin/epac-run --version
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "epac [0-9]+\\.[0-9]+\\.[0-9]+")
    message(FATAL_ERROR "moved epac-run --version failed (${rc}): ${out}${err}")
  endif()
  message(STATUS "moved epac-run --version: ${out}")
endif()

# The moved package refuses a Kokkos older than epac's minimum (a fake Kokkos 3.0.0 prefix).
set(fake ${WORK_DIR}/fake-kokkos-3.0)
file(WRITE ${fake}/lib/cmake/Kokkos/KokkosConfig.cmake
     "set(Kokkos_VERSION 3.0.0)\nadd_library(Kokkos::kokkos INTERFACE IMPORTED)\n")
file(WRITE ${fake}/lib/cmake/Kokkos/KokkosConfigVersion.cmake
     "set(PACKAGE_VERSION 3.0.0)\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n")
file(WRITE ${WORK_DIR}/old-kokkos/CMakeLists.txt
     "cmake_minimum_required(VERSION 3.16)\nproject(old_kokkos NONE)\nfind_package(epac REQUIRED)\n")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/old-kokkos -B ${WORK_DIR}/old-kokkos/build
  "-DCMAKE_PREFIX_PATH=${moved}" "-DKokkos_ROOT=${fake}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES "needs Kokkos >= [0-9.]+; found 3.0.0")
  message(FATAL_ERROR "find_package(epac) accepted Kokkos 3.0.0 or said something else: ${out}${err}")
endif()
message(STATUS "find_package(epac) with Kokkos 3.0.0 refused, as it should be")
