# EPAC_ARCH and EPAC_NO_MATH_ERRNO (cmake/EpacArchFlags.cmake): configures epac alone (no tests,
# benchmarks or drivers) three times and checks the flags it records for its own executables.
#   cmake -DEPAC_SOURCE=... -DWORK_DIR=... -DKOKKOS_ROOT=... -P arch_flags.cmake
function(configure_epac name out_rc out_log)
  set(dir ${WORK_DIR}/${name})
  file(REMOVE_RECURSE ${dir})
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${EPAC_SOURCE} -B ${dir} -DKokkos_ROOT=${KOKKOS_ROOT}
                          -DEPAC_BUILD_TESTS=OFF -DEPAC_BUILD_BENCH=OFF -DEPAC_BUILD_DRIVERS=OFF ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_log} "${o}${e}" PARENT_SCOPE)
endfunction()

# default: portable (no -march), -fno-math-errno
configure_epac(default rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "default configure failed:\n${log}")
endif()
file(READ ${WORK_DIR}/default/epac-build-flags.txt flags)
if(flags MATCHES "-march" OR NOT flags MATCHES "-fno-math-errno")
  message(FATAL_ERROR "default flags '${flags}': want no -march and -fno-math-errno")
endif()

# an explicit architecture every x86-64 GCC/Clang knows, and errno kept
configure_epac(explicit rc log -DEPAC_ARCH=x86-64 -DEPAC_NO_MATH_ERRNO=OFF)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "EPAC_ARCH=x86-64 configure failed:\n${log}")
endif()
file(READ ${WORK_DIR}/explicit/epac-build-flags.txt flags)
if(NOT flags MATCHES "-march=x86-64" OR flags MATCHES "-fno-math-errno")
  message(FATAL_ERROR "EPAC_ARCH=x86-64, EPAC_NO_MATH_ERRNO=OFF flags '${flags}'")
endif()

# a value the compiler rejects: configure fails and names the option and the value
configure_epac(bogus rc log -DEPAC_ARCH=no-such-cpu)
if(rc EQUAL 0 OR NOT log MATCHES "EPAC_ARCH=no-such-cpu")
  message(FATAL_ERROR "EPAC_ARCH=no-such-cpu: want a configure error naming it, got rc ${rc}:\n${log}")
endif()
message(STATUS "arch flags: default, explicit and rejected values as documented")
