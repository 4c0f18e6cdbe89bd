# The CPU guard (cmake/arch/cpu_guard.cpp) of executables built with an -march:
#   cmake -DEXES="a;b" -DVALGRIND=... -DAVX512=ON|OFF -P cpu_guard.cmake
# Each executable runs on this CPU and reaches main; where the build uses AVX-512 and valgrind
# (3.19: no AVX-512 in its simulated CPU) is there, each also runs under valgrind, and the guard
# must stop it before main with exit status 1 and a message naming the missing extension.
list(GET EXES 0 main_exe)
execute_process(COMMAND ${main_exe} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "main ran")
  message(FATAL_ERROR "${main_exe} on this CPU: rc ${rc}, want 0 and main:\n${out}${err}")
endif()
if(NOT AVX512 OR NOT VALGRIND)
  message(STATUS "no AVX-512 in this build's flags (or no valgrind): the stopping guard not exercised")
  return()
endif()
foreach(exe IN LISTS EXES)
  execute_process(COMMAND ${VALGRIND} -q ${exe} --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 120)
  if(NOT rc EQUAL 1 OR out MATCHES "main ran|[Uu]sage" OR NOT err MATCHES "lacks: [^\n]*avx512f"
     OR NOT err MATCHES "-DEPAC_ARCH=portable")
    message(FATAL_ERROR "${exe} on a CPU without AVX-512 (valgrind): rc ${rc}, want 1 and the guard's message "
                        "before main:\n${out}${err}")
  endif()
  message(STATUS "${exe}: stopped by the guard on a CPU without AVX-512")
endforeach()
