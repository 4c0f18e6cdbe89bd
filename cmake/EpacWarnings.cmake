# Warnings for epac's own targets (tests, bench, drivers); the library itself adds none to hosts.
function(epac_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-missing-field-initializers)
  endif()
endfunction()

# Targets that compile Eigen: GCC 12.1-12.2 warn "'__Y' may be used uninitialized" inside their
# own AVX-512 intrinsics headers (avx512fintrin.h, _mm512_extractf64x4_pd's deliberately undefined
# operand) wherever Eigen's AVX-512 reductions are inlined, i.e. in every native build on an
# AVX-512 machine. A false positive of the compiler (GCC bug 105593, fixed in 12.3), so the
# warning is off for these targets with those compilers only.
function(epac_eigen_warnings target)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
     AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 12.3)
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
endfunction()
