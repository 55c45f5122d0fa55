# A hard case must run to its end time (or settle) without NaN and with bounded total energy:
# `impactsph run` exits 0 and summary.json's energy drift is below 10 %.
# -DEXE=... -DOUT=... -DARGS="case;--spacing;2mm;..." (a CMake list)
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} run ${ARGS} --out ${OUT} --quiet --set output.vtu=false
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph run failed (${rc}):\n${out}\n${err}")
endif()
file(READ ${OUT}/summary.json summary)
string(JSON drift GET "${summary}" totals energy_drift_relative)
string(JSON steps GET "${summary}" steps)
message(STATUS "${steps} steps, energy drift ${drift}\n${out}")
if(drift GREATER 0.1 OR drift LESS -0.1)
  message(FATAL_ERROR "total energy drifted by ${drift} (more than 10 %)")
endif()
