# Code-generation flags for epac's own executables (tests, benchmarks, drivers). The library target
# epac::epac adds none to a host: the kernels are templates compiled in the host's own files, so a
# host chooses its own flags (docs/install.md says which ones epac measured).
#   EPAC_ARCH          "auto" (default): -march=native where a probe compiled with it runs on this
#                      machine (a CPU check at configure time: every extension the flag enables is
#                      present and enabled by the OS), else the compiler's baseline; the configure
#                      output says which and why. Executables built so run on the machine that
#                      built them: for ones that move, choose "portable" or an explicit level.
#                      "portable": the compiler's baseline, runs on any x86-64 (or other) machine;
#                      "native": -march=native without the probe; any other value X: -march=X
#                      (e.g. znver4, skylake-avx512, x86-64-v3).
#   EPAC_NO_MATH_ERRNO ON (default): -fno-math-errno. epac never reads errno and checks every
#                      sqrt/cbrt/log argument itself, so this changes no result; it lets the
#                      compiler use the square-root instruction without a library fallback call.
#   EPAC_NO_GATHER     ON (default): with GCC on x86-64 and an -march, -mtune-ctrl=^use_gather:
#                      no vector gather instructions for 8 or more elements (GCC 12's znver3
#                      tuning, what its -march=native gives on this project's AMD EPYC, uses
#                      them). The contact lanes load each lane's particle state from its own
#                      index; in float (8 lanes in one vector) g++ gathered them, and scalar
#                      loads ran 9-12% faster there (docs/performance.md, "Build flags"). Loads
#                      of the same values: no result changes. Double code is the same (GCC 12
#                      loads 4 elements one by one on znver3 already).
# GPU builds (Kokkos with CUDA or HIP) take neither: the kernels' code is the device's.
# Sets EPAC_ARCH_RESOLVED (what EPAC_ARCH became) and EPAC_OWN_AVX512 (the flags enable AVX-512).
set(EPAC_ARCH "auto" CACHE STRING "auto | portable | native | a -march value, for epac's own executables")
# what auto tries; tests set a value the compiler rejects to see the fallback
set(EPAC_ARCH_AUTO_MARCH "native" CACHE STRING "the -march value EPAC_ARCH=auto tries")
# what runs the probe (empty: nothing); tests run it under valgrind, a CPU without AVX-512
set(EPAC_ARCH_PROBE_LAUNCHER "" CACHE STRING "a command list the auto probe runs under")
mark_as_advanced(EPAC_ARCH_AUTO_MARCH EPAC_ARCH_PROBE_LAUNCHER)
option(EPAC_NO_MATH_ERRNO "-fno-math-errno for epac's own executables" ON)
option(EPAC_NO_GATHER "GCC on x86-64 with an -march: no vector gathers (-mtune-ctrl=^use_gather)" ON)

# auto: builds the probe with -march=${EPAC_ARCH_AUTO_MARCH} and runs it; out_arch: that value or
# portable, out_why: the reason.
function(epac_resolve_auto_arch out_arch out_why)
  set(_m ${EPAC_ARCH_AUTO_MARCH})
  if(CMAKE_CROSSCOMPILING)
    set(${out_arch} portable PARENT_SCOPE)
    set(${out_why} "cross-compiling: this machine's CPU is not the target's" PARENT_SCOPE)
    return()
  endif()
  string(MAKE_C_IDENTIFIER "EPAC_HAS_MARCH_${_m}" _var)
  check_cxx_compiler_flag("-march=${_m}" ${_var})
  if(NOT ${_var})
    set(${out_arch} portable PARENT_SCOPE)
    set(${out_why} "the compiler rejects -march=${_m}" PARENT_SCOPE)
    return()
  endif()
  # built and run afresh at every configure: a build folder may meet another CPU
  set(_dir ${PROJECT_BINARY_DIR}/epac-arch-probe)
  set(_exe ${_dir}/epac-arch-probe${CMAKE_EXECUTABLE_SUFFIX})
  file(REMOVE ${_exe})
  unset(EPAC_ARCH_PROBE_COMPILE CACHE)
  try_compile(EPAC_ARCH_PROBE_COMPILE ${_dir}
              SOURCES ${CMAKE_CURRENT_LIST_DIR}/arch/arch_probe.cpp ${CMAKE_CURRENT_LIST_DIR}/arch/cpu_guard.cpp
              COMPILE_DEFINITIONS -march=${_m} COPY_FILE ${_exe})
  if(NOT EPAC_ARCH_PROBE_COMPILE)
    set(${out_arch} portable PARENT_SCOPE)
    set(${out_why} "the probe did not compile with -march=${_m}" PARENT_SCOPE)
    return()
  endif()
  execute_process(COMMAND ${EPAC_ARCH_PROBE_LAUNCHER} ${_exe} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
                  ERROR_VARIABLE _err TIMEOUT 60)
  if(_out STREQUAL "")
    set(_out "${_err}")  # the guard and a crash say why on stderr
  endif()
  if(_out MATCHES "lacks:([^\n]*)")
    set(_out "missing${CMAKE_MATCH_1}")  # the guard's list, without its advice
  endif()
  string(STRIP "${_out}" _out)
  string(REPLACE "\n" "; " _out "${_out}")
  if(NOT _rc STREQUAL "0")
    set(${out_arch} portable PARENT_SCOPE)
    set(${out_why} "a probe built with -march=${_m} failed on this CPU (${_rc}: ${_out})" PARENT_SCOPE)
  else()
    set(${out_arch} ${_m} PARENT_SCOPE)
    set(${out_why} "a probe built with -march=${_m} ran on this CPU" PARENT_SCOPE)
  endif()
endfunction()

set(EPAC_OWN_TARGET_FLAGS "")
set(_march "")
if(NOT EPAC_GPU_KOKKOS AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCXXCompilerFlag)
  set(EPAC_ARCH_RESOLVED ${EPAC_ARCH})
  if(EPAC_ARCH STREQUAL "auto")
    epac_resolve_auto_arch(EPAC_ARCH_RESOLVED _why)
    message(STATUS "epac: EPAC_ARCH=auto -> ${EPAC_ARCH_RESOLVED}: ${_why}")
  endif()
  if(NOT EPAC_ARCH_RESOLVED STREQUAL "portable")
    set(_march "-march=${EPAC_ARCH_RESOLVED}")
    string(MAKE_C_IDENTIFIER "EPAC_HAS_MARCH_${EPAC_ARCH_RESOLVED}" _var)
    check_cxx_compiler_flag("${_march}" ${_var})
    if(NOT ${_var})
      message(FATAL_ERROR "epac: EPAC_ARCH=${EPAC_ARCH}: the compiler rejects ${_march} (use portable, native or a "
                          "-march value it knows)")
    endif()
    list(APPEND EPAC_OWN_TARGET_FLAGS ${_march})
    if(EPAC_NO_GATHER AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
      check_cxx_compiler_flag("-mtune-ctrl=^use_gather" EPAC_HAS_TUNE_CTRL_NO_GATHER)
      if(EPAC_HAS_TUNE_CTRL_NO_GATHER)
        list(APPEND EPAC_OWN_TARGET_FLAGS "-mtune-ctrl=^use_gather")
      endif()
    endif()
  endif()
  if(EPAC_NO_MATH_ERRNO)
    list(APPEND EPAC_OWN_TARGET_FLAGS -fno-math-errno)
  endif()
else()
  set(EPAC_ARCH_RESOLVED portable)
endif()
if((EPAC_GPU_KOKKOS OR NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang") AND NOT EPAC_ARCH MATCHES "^(auto|portable)$")
  message(WARNING "epac: EPAC_ARCH=${EPAC_ARCH} ignored (GPU build or a compiler other than GCC/Clang)")
endif()
add_compile_options(${EPAC_OWN_TARGET_FLAGS})
# An executable built with an -march checks the CPU it starts on (cmake/arch/cpu_guard.cpp):
# the top CMakeLists.txt links EPAC_CPU_GUARD into every executable of epac's own.
set(EPAC_CPU_GUARD "")
if(_march AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64" AND (EPAC_BUILD_TESTS OR EPAC_BUILD_BENCH OR EPAC_BUILD_DRIVERS))
  add_library(epac_cpu_guard OBJECT ${CMAKE_CURRENT_LIST_DIR}/arch/cpu_guard.cpp)
  set_target_properties(epac_cpu_guard PROPERTIES POSITION_INDEPENDENT_CODE ON)
  set(EPAC_CPU_GUARD epac_cpu_guard)
endif()
# valgrind (bench/roofline/roofline.py) cannot execute AVX-512: tests/bench/CMakeLists.txt asks
set(EPAC_OWN_AVX512 OFF)
if(EPAC_OWN_TARGET_FLAGS)
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "${EPAC_OWN_TARGET_FLAGS}")
  string(REPLACE ";" " " CMAKE_REQUIRED_FLAGS "${CMAKE_REQUIRED_FLAGS}")
  unset(EPAC_OWN_AVX512_MACRO CACHE)
  check_cxx_source_compiles("#ifndef __AVX512F__\n#error no AVX-512\n#endif\nint main() { return 0; }"
                            EPAC_OWN_AVX512_MACRO)
  unset(CMAKE_REQUIRED_FLAGS)
  set(EPAC_OWN_AVX512 ${EPAC_OWN_AVX512_MACRO})
endif()
# What the benchmarks report next to their numbers (bench/peers/side_by_side.py, roofline.py).
string(TOUPPER "${CMAKE_BUILD_TYPE}" _bt)
string(JOIN " " _flags ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} ${CMAKE_CXX_FLAGS}
       ${CMAKE_CXX_FLAGS_${_bt}} ${EPAC_OWN_TARGET_FLAGS})
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/epac-build-flags.txt "${_flags}\n")
message(STATUS "epac: own executables built with: ${_flags}")
