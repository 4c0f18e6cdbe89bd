# EPAC_ARCH and EPAC_NO_MATH_ERRNO (cmake/EpacArchFlags.cmake): configures epac alone (no tests,
# benchmarks or drivers) several times and checks the flags it records for its own executables.
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

cmake_host_system_information(RESULT _arch QUERY OS_PLATFORM)
set(EPAC_HOST_X86_64 OFF)
if(_arch MATCHES "x86_64|AMD64")
  set(EPAC_HOST_X86_64 ON)
endif()

# default: auto, i.e. -march=native where a probe built with it runs here, else none; the configure
# output names the choice and its reason, and the recorded flags follow it; -fno-math-errno
configure_epac(default rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "default configure failed:\n${log}")
endif()
file(READ ${WORK_DIR}/default/epac-build-flags.txt flags)
if(NOT log MATCHES "EPAC_ARCH=auto -> ([^:]+): ([^\n]*)")
  message(FATAL_ERROR "default configure does not say what EPAC_ARCH=auto chose:\n${log}")
endif()
set(chosen ${CMAKE_MATCH_1})
set(why ${CMAKE_MATCH_2})
if(chosen STREQUAL "native")
  if(NOT flags MATCHES "-march=native" OR NOT why MATCHES "ran on this CPU")
    message(FATAL_ERROR "auto chose native ('${why}'), flags '${flags}'")
  endif()
elseif(chosen STREQUAL "portable")
  if(flags MATCHES "-march")
    message(FATAL_ERROR "auto chose portable ('${why}'), flags '${flags}'")
  endif()
  message(STATUS "this machine's compiler or CPU refused -march=native: ${why}")
else()
  message(FATAL_ERROR "auto chose '${chosen}': want native or portable")
endif()
if(NOT flags MATCHES "-fno-math-errno")
  message(FATAL_ERROR "default flags '${flags}': want -fno-math-errno")
endif()
# GCC on x86-64 with an -march: no vector gathers (EPAC_NO_GATHER), and never without an -march
if(flags MATCHES "^GNU" AND flags MATCHES "-march" AND EPAC_HOST_X86_64 AND NOT flags MATCHES "-mtune-ctrl=\\^use_gather")
  message(FATAL_ERROR "default flags '${flags}': want -mtune-ctrl=^use_gather (GCC, x86-64, an -march)")
endif()
if(NOT flags MATCHES "-march" AND flags MATCHES "use_gather")
  message(FATAL_ERROR "default flags '${flags}': a gather tuning without an -march")
endif()

# portable: no -march whatever the machine
configure_epac(portable rc log -DEPAC_ARCH=portable)
file(READ ${WORK_DIR}/portable/epac-build-flags.txt flags)
if(NOT rc EQUAL 0 OR flags MATCHES "-march")
  message(FATAL_ERROR "EPAC_ARCH=portable: rc ${rc}, flags '${flags}'")
endif()

# auto where the compiler rejects the candidate: falls back to portable and says why (an explicit
# value the compiler rejects stops the configure instead, below)
configure_epac(auto_rejected rc log -DEPAC_ARCH_AUTO_MARCH=no-such-cpu)
file(READ ${WORK_DIR}/auto_rejected/epac-build-flags.txt flags)
if(NOT rc EQUAL 0 OR flags MATCHES "-march" OR NOT log MATCHES "auto -> portable: the compiler rejects -march=no-such-cpu")
  message(FATAL_ERROR "auto with a rejected candidate: rc ${rc}, flags '${flags}':\n${log}")
endif()

# auto where the CPU lacks what the candidate enables: the probe fails (its list of missing
# extensions, or an illegal instruction if the compiler used one before the check) and auto falls
# back. On a CPU without AVX-512, by asking for it; on one with it, by running the probe under
# valgrind, whose simulated CPU (3.19) has no AVX-512 and reports none. Neither possible: said,
# not passed silently.
set(lacking "")
set(launcher "")
if(EXISTS /proc/cpuinfo)
  file(STRINGS /proc/cpuinfo cpu_flags REGEX "^flags" LIMIT_COUNT 1)
  find_program(VALGRIND valgrind)
  if(NOT cpu_flags MATCHES " avx2( |$)")
    set(lacking haswell)
  elseif(NOT cpu_flags MATCHES " avx512f( |$)")
    set(lacking skylake-avx512)
  elseif(VALGRIND)
    set(lacking native)
    set(launcher "-DEPAC_ARCH_PROBE_LAUNCHER=${VALGRIND}")
  endif()
endif()
if(lacking)
  configure_epac(auto_lacking rc log -DEPAC_ARCH_AUTO_MARCH=${lacking} ${launcher})
  file(READ ${WORK_DIR}/auto_lacking/epac-build-flags.txt flags)
  if(NOT rc EQUAL 0 OR flags MATCHES "-march"
     OR NOT log MATCHES "auto -> portable: a probe built with -march=${lacking} failed on this CPU \\(")
    message(FATAL_ERROR "auto with -march=${lacking} on a CPU without it (${launcher}): rc ${rc}, flags '${flags}':\n${log}")
  endif()
  message(STATUS "auto, -march=${lacking} on a CPU without it ${launcher}: fell back to portable")
else()
  message(WARNING "the fallback on a CPU that lacks the candidate's extensions was not exercised: "
                  "this CPU has AVX-512 and there is no valgrind to hide it")
endif()

# an explicit architecture every x86-64 GCC/Clang knows, errno kept, gathers left to the compiler
configure_epac(explicit rc log -DEPAC_ARCH=x86-64 -DEPAC_NO_MATH_ERRNO=OFF -DEPAC_NO_GATHER=OFF)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "EPAC_ARCH=x86-64 configure failed:\n${log}")
endif()
file(READ ${WORK_DIR}/explicit/epac-build-flags.txt flags)
if(NOT flags MATCHES "-march=x86-64" OR flags MATCHES "-fno-math-errno" OR flags MATCHES "use_gather")
  message(FATAL_ERROR "EPAC_ARCH=x86-64, EPAC_NO_MATH_ERRNO=OFF, EPAC_NO_GATHER=OFF flags '${flags}'")
endif()

# a value the compiler rejects: configure fails and names the option and the value
configure_epac(bogus rc log -DEPAC_ARCH=no-such-cpu)
if(rc EQUAL 0 OR NOT log MATCHES "EPAC_ARCH=no-such-cpu")
  message(FATAL_ERROR "EPAC_ARCH=no-such-cpu: want a configure error naming it, got rc ${rc}:\n${log}")
endif()
message(STATUS "arch flags: auto, portable, explicit and rejected values as documented")
