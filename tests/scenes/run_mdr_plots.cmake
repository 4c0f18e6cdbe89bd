# ctest mdr_scenes_plots: every MDR scene (one thread; the packing with 200 steps) and the plot script into
# OUT, then every expected PNG must exist and be non-empty.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND sh ${RUN} ${EXE} ${OUT} 1 200 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "run_mdr_scenes.sh failed (${rc})")
endif()
foreach(png mdr_two_flats_force mdr_two_flats_force_all mdr_two_flats_area mdr_two_flats_pressure
            mdr_two_flats_volume mdr_adhesive mdr_die_compaction mdr_pairs)
  if(NOT EXISTS ${OUT}/${png}.png)
    message(FATAL_ERROR "missing ${OUT}/${png}.png")
  endif()
  file(SIZE ${OUT}/${png}.png sz)
  if(sz LESS 10000)
    message(FATAL_ERROR "${OUT}/${png}.png is only ${sz} bytes")
  endif()
endforeach()
