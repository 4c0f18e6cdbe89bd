# Runs epac-run (EXE) on SCENE twice, with --threads 1 and --threads 2 and the extra arguments
# ARGS (comma-separated, e.g. --deterministic,--steps,3000), and requires byte-identical output
# files FILES (comma-separated, e.g. timeseries.csv,particles.csv). summary.json is not compared: it holds
# timings and the thread count. APPEND (optional): lines appended to a copy of the scene, which
# then runs instead (settling.toml ends with its [run] table, so they land there).
cmake_minimum_required(VERSION 3.16)
string(REPLACE "," ";" ARGS "${ARGS}")
string(REPLACE "," ";" FILES "${FILES}")
if(DEFINED APPEND)
  file(READ ${SCENE} text)
  string(REPLACE "|" "\n" lines "${APPEND}")
  file(MAKE_DIRECTORY ${OUT})
  file(WRITE ${OUT}/scene.toml "${text}\n${lines}\n")
  set(SCENE ${OUT}/scene.toml)
endif()
foreach(t 1 2)
  file(REMOVE_RECURSE ${OUT}/threads${t})
  execute_process(COMMAND ${EXE} ${SCENE} --quiet --threads ${t} --out ${OUT}/threads${t} ${ARGS}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--threads ${t}: exit status ${rc}\n--- stdout\n${out}--- stderr\n${err}")
  endif()
endforeach()
foreach(f ${FILES})
  foreach(t 1 2)
    if(NOT EXISTS ${OUT}/threads${t}/${f})
      message(FATAL_ERROR "--threads ${t} wrote no ${f}")
    endif()
  endforeach()
  file(SIZE ${OUT}/threads1/${f} size)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/threads1/${f} ${OUT}/threads2/${f}
                  RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "${f} differs between 1 and 2 threads (${OUT}/threads1, ${OUT}/threads2)")
  endif()
  message(STATUS "${f}: ${size} bytes, identical on 1 and 2 threads")
endforeach()
