# `impactsph ballistic-limit --backend gpu --precision float`: the search runs the port (its host build
# without a GPU), records the solver in ballistic.json, run.json and each summary.json, reuses its own
# finished runs, and does not take them for the reference's: a reference search in the same folder runs
# its two ends again.
file(REMOVE_RECURSE ${OUT})
set(common ${CASE} --from 50 --to 600 --jobs 2 --spacing 2.5mm --set time.end=40us --set output.vtu=false
           --set output.picture=false --out ${OUT})
execute_process(COMMAND ${EXE} ballistic-limit ${common} --tolerance 300 --backend gpu --precision float
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ballistic-limit --backend gpu failed (${rc}):\n${out}\n${err}")
endif()
if(NOT out MATCHES "solver: gpu port \\(float")
  message(FATAL_ERROR "the banner does not name the port:\n${out}")
endif()
file(READ ${OUT}/ballistic.json json)
string(JSON backend GET "${json}" backend)
string(JSON precision GET "${json}" precision)
if(NOT backend STREQUAL "gpu" OR NOT precision STREQUAL "float")
  message(FATAL_ERROR "ballistic.json says backend ${backend}, precision ${precision}")
endif()
file(READ ${OUT}/v_50/summary.json summary)
string(JSON solver GET "${summary}" solver)
if(NOT solver MATCHES "^gpu port \\(float")
  message(FATAL_ERROR "v_50 ran on ${solver}")
endif()
file(READ ${OUT}/v_50/run.json run)
string(JSON run_backend GET "${run}" backend)
if(NOT run_backend STREQUAL "gpu")
  message(FATAL_ERROR "v_50/run.json says backend ${run_backend}")
endif()

# Again on the port: every run is taken from the folder.
execute_process(COMMAND ${EXE} ballistic-limit ${common} --tolerance 300 --backend gpu --precision float
                RESULT_VARIABLE rc OUTPUT_VARIABLE again ERROR_VARIABLE err)
string(REGEX MATCHALL "finished earlier in this folder" reused "${again}")
list(LENGTH reused n_reused)
if(NOT rc EQUAL 0 OR n_reused LESS 4)
  message(FATAL_ERROR "the second port search reused ${n_reused} runs (rc ${rc}):\n${again}\n${err}")
endif()

# The reference in the same folder: its two ends are run, not read from the port's summaries.
execute_process(COMMAND ${EXE} ballistic-limit ${common} --tolerance 550
                RESULT_VARIABLE rc OUTPUT_VARIABLE ref ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR ref MATCHES "finished earlier in this folder" OR NOT ref MATCHES "solver: reference \\(double\\)")
  message(FATAL_ERROR "the reference search took the port's runs (rc ${rc}):\n${ref}\n${err}")
endif()
file(READ ${OUT}/v_50/summary.json summary)
string(JSON solver GET "${summary}" solver)
if(NOT solver MATCHES "^reference")
  message(FATAL_ERROR "v_50 now holds ${solver}")
endif()

# A float reference is refused before any run.
execute_process(COMMAND ${EXE} ballistic-limit ${common} --precision float RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "the reference solver runs in double only")
  message(FATAL_ERROR "--precision float on the reference was not refused (rc ${rc}): ${err}")
endif()
