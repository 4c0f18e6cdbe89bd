# Runs epac-sticking-velocity (EXE) on SCENE with --out OUT and checks that the JSON's V_ys lies
# in [LO, HI] (if(LESS) compares as doubles; string(JSON) needs CMake >= 3.19 here).
cmake_minimum_required(VERSION 3.19)
execute_process(COMMAND ${EXE} ${SCENE} --out ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit ${rc}\n--- stdout\n${out}--- stderr\n${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit status ${rc}")
endif()
file(READ ${OUT}/sticking_velocity.json json)
string(JSON v GET "${json}" V_ys)
if(v LESS LO OR v GREATER HI)
  message(FATAL_ERROR "V_ys = ${v} m/s is outside [${LO}, ${HI}]")
endif()
message(STATUS "V_ys = ${v} m/s in [${LO}, ${HI}]")
