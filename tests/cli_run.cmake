# Runs a short case through `impactsph run` and checks that every output a user opens is there, then
# restarts the finished run (which must find its checkpoint and end at once).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} run ${CASE} --spacing 1mm --set time.end=2us --out ${OUT} --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph run failed (${rc}):\n${out}\n${err}")
endif()
if(NOT out MATCHES "done: t = 2 us")
  message(FATAL_ERROR "unexpected output:\n${out}")
endif()
foreach(f summary.json particles.pvd particles_000000.vtu history_bar.csv history_flyer.csv totals.csv checkpoint.bin run.json)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "missing output ${f}")
  endif()
endforeach()
file(GLOB leftovers ${OUT}/*.tmp-*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
file(READ ${OUT}/summary.json summary)
foreach(key particles steps wall_time_s particle_steps_per_second mean_neighbours bodies specified generated
        lattice_spacing_m geometry_warnings)
  if(NOT summary MATCHES "\"${key}\"")
    message(FATAL_ERROR "summary.json lacks ${key}")
  endif()
endforeach()
execute_process(COMMAND ${EXE} run --restart ${OUT} --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "done: t = 2 us")
  message(FATAL_ERROR "restart of a finished run failed (${rc}):\n${out}\n${err}")
endif()
# --end continues the finished run to a later end time; a later restart keeps it; it is refused without
# --restart, when the run is already past it, and without a time unit. expect_run(RC_ZERO STREAM REGEX ...):
# run the program with the remaining arguments, fail unless it exits 0 (RC_ZERO true) or not (false) and
# its STREAM (out or err) matches REGEX.
function(expect_run rc_zero stream regex)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if((rc_zero AND NOT rc EQUAL 0) OR (NOT rc_zero AND rc EQUAL 0) OR NOT ${stream} MATCHES "${regex}")
    message(FATAL_ERROR "impactsph ${ARGN}: exit ${rc}, expected ${stream} to match ${regex}:\n${out}\n${err}")
  endif()
endfunction()
expect_run(TRUE out "done: t = 3 us" run --restart ${OUT} --end 3us --quiet)
file(READ ${OUT}/summary.json summary)
if(NOT summary MATCHES "\"end_time_s\": 3(\\.0*[0-9]*)?e-0?6")
  message(FATAL_ERROR "summary.json after --end 3us:\n${summary}")
endif()
expect_run(TRUE out "done: t = 3 us" run --restart ${OUT} --quiet)
expect_run(FALSE err "--end 1us: the run in [^\n]* is already at 3 us; give a later end time"
           run --restart ${OUT} --end 1us --quiet)
expect_run(FALSE err "--end 5: give the time with its unit" run --restart ${OUT} --end 5 --quiet)
expect_run(FALSE err "--end: \"5mm\" is a length; expected a time" run --restart ${OUT} --end 5mm --quiet)
expect_run(FALSE err "--end 3us continues a run to a later end time and goes with --restart DIR"
           run ${CASE} --end 3us --out ${OUT}-new --quiet)
