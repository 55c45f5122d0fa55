# The ceramic tile case (cases/ceramic-tile) through `impactsph run`.
#   -DMODE=ci: a coarse, short run (2.54 mm, 10 us, one thread): it must run without NaN, keep the total energy within
#     10 %, write the tile and rod observables, and carry damage and the bulking pressure in the VTU; the
#     rod must have slowed down and the tile must be damaged.
#   -DMODE=validation: the case as committed (0.79375 mm, 60 us): residual velocity and residual mass within
#     the targets of the case's expected.toml (the experiment of Nemat-Nasser et al. 2002), checked by
#     tests/check_expected.py.
# -DEXE=... -DCASE=... -DOUT=...
file(REMOVE_RECURSE ${OUT})
if(MODE STREQUAL "ci")
  set(args --spacing 2.54mm --threads 1 --set time.end=10us --set time.frame_interval=10us)
else()
  set(args --threads 2 --set output.vtu=false)
endif()
execute_process(COMMAND ${EXE} run ${CASE} ${args} --out ${OUT} --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph run failed (${rc}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
file(READ ${OUT}/summary.json summary)
string(JSON drift GET "${summary}" totals energy_drift_relative)
if(drift GREATER 0.1 OR drift LESS -0.1)
  message(FATAL_ERROR "total energy drifted by ${drift} (more than 10 %)")
endif()
foreach(key residual_velocity residual_mass eroded_mass damage_fraction)
  string(JSON ${key} ERROR_VARIABLE missing GET "${summary}" observables ${key})
  if(missing)
    message(FATAL_ERROR "summary.json lacks observables.${key}: ${missing}")
  endif()
endforeach()
if(MODE STREQUAL "ci")
  if(NOT residual_velocity LESS 903.0 OR NOT residual_velocity GREATER 0)
    message(FATAL_ERROR "the rod did not slow down: residual velocity ${residual_velocity} m/s")
  endif()
  if(NOT damage_fraction GREATER 0)
    message(FATAL_ERROR "no damage in the tile")
  endif()
  file(GLOB frames ${OUT}/particles_*.vtu)
  list(GET frames -1 last)
  file(READ ${last} vtu LIMIT 20000)
  foreach(field damage bulking_pressure smoothing_length)
    if(NOT vtu MATCHES "Name=\"${field}\"")
      message(FATAL_ERROR "the VTU lacks ${field}")
    endif()
  endforeach()
else()
  get_filename_component(case_dir ${CASE} DIRECTORY)
  execute_process(COMMAND python3 ${CMAKE_CURRENT_LIST_DIR}/check_expected.py ${case_dir}/expected.toml
                          ${OUT}/summary.json residual_velocity residual_mass
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the ceramic tile misses its expected answers:\n${out}${err}")
  endif()
endif()
