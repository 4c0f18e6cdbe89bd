# Code-generation flags for epac's own executables (tests, benchmarks, drivers). The library target
# epac::epac adds none to a host: the kernels are templates compiled in the host's own files, so a
# host chooses its own flags (docs/install.md says which ones epac measured).
#   EPAC_ARCH          "portable" (default): the compiler's baseline, runs on any x86-64 (or other)
#                      machine the README's commands meet; "native": -march=native, only for the
#                      machine that builds (checked at configure time); any other value X: -march=X
#                      (e.g. znver4, skylake-avx512, x86-64-v3).
#   EPAC_NO_MATH_ERRNO ON (default): -fno-math-errno. epac never reads errno and checks every
#                      sqrt/cbrt/log argument itself, so this changes no result; it lets the
#                      compiler use the square-root instruction without a library fallback call.
# GPU builds (Kokkos with CUDA or HIP) take neither: the kernels' code is the device's.
set(EPAC_ARCH "portable" CACHE STRING "portable | native | a -march value, for epac's own executables")
option(EPAC_NO_MATH_ERRNO "-fno-math-errno for epac's own executables" ON)

set(EPAC_OWN_TARGET_FLAGS "")
if(NOT EPAC_GPU_KOKKOS AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  include(CheckCXXCompilerFlag)
  if(NOT EPAC_ARCH STREQUAL "portable")
    set(_march "-march=${EPAC_ARCH}")
    string(MAKE_C_IDENTIFIER "EPAC_HAS_MARCH_${EPAC_ARCH}" _var)
    check_cxx_compiler_flag("${_march}" ${_var})
    if(NOT ${_var})
      message(FATAL_ERROR "epac: EPAC_ARCH=${EPAC_ARCH}: the compiler rejects ${_march} (use portable, native or a "
                          "-march value it knows)")
    endif()
    list(APPEND EPAC_OWN_TARGET_FLAGS ${_march})
  endif()
  if(EPAC_NO_MATH_ERRNO)
    list(APPEND EPAC_OWN_TARGET_FLAGS -fno-math-errno)
  endif()
elseif(NOT EPAC_ARCH STREQUAL "portable")
  message(WARNING "epac: EPAC_ARCH=${EPAC_ARCH} ignored (GPU build or a compiler other than GCC/Clang)")
endif()
add_compile_options(${EPAC_OWN_TARGET_FLAGS})
# What the benchmarks report next to their numbers (bench/peers/side_by_side.py, roofline.py).
string(TOUPPER "${CMAKE_BUILD_TYPE}" _bt)
string(JOIN " " _flags ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} ${CMAKE_CXX_FLAGS}
       ${CMAKE_CXX_FLAGS_${_bt}} ${EPAC_OWN_TARGET_FLAGS})
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/epac-build-flags.txt "${_flags}\n")
message(STATUS "epac: own executables built with: ${_flags}")
