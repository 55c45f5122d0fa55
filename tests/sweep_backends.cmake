# `impactsph sweep` over the backend and precision axes (tests/data/sweeps/backend_precision.toml: the
# elastic wave at 1 mm to 0.5 us, 13 steps, for every combination of reference/gpu and double/float).
# Each run must get its own --backend/--precision, record them (sweep_run.json, run.json, the table) and
# run the solver they name (summary.json "solver"); the reference refuses float, so that run fails with
# the run command's error and the sweep exits 3. Started again, the sweep skips the three complete runs
# (the backend and precision are part of what makes a run the same run). The Slurm script passes the
# same flags. -DEXE=... -DSWEEP=... -DOUT=...
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CMAKE_COMMAND} -E env OMP_WAIT_POLICY=PASSIVE ${EXE} sweep ${SWEEP} --out ${OUT} --jobs 1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 3 OR NOT out MATCHES "3 of 4 runs complete \\(3 run now, 0 skipped as complete\\), 0 stopped, 1 failed")
  message(FATAL_ERROR "the sweep should complete 3 runs and fail the reference in float, exit 3 (${rc}):\n${out}\n${err}")
endif()

# backend | precision | status | how the solver that ran names itself (its start; - when none ran)
set(expect
    "reference|double|done|reference (double, OpenMP)"
    "reference|float|failed|-"
    "gpu|double|done|gpu port (double, "
    "gpu|float|done|gpu port (float, ")
file(STRINGS ${OUT}/sweep.csv rows)
list(GET rows 0 head)
if(NOT head MATCHES "^run,spacing,backend,precision,status,particles,steps,")
  message(FATAL_ERROR "sweep.csv should have the backend and precision columns: ${head}")
endif()
foreach(e ${expect})
  string(REPLACE "|" ";" e "${e}")
  list(GET e 0 backend)
  list(GET e 1 precision)
  list(GET e 2 status)
  list(GET e 3 solver)
  set(run spacing-1mm__backend-${backend}__precision-${precision})
  set(dir ${OUT}/${run})

  # What the sweep recorded: the parameters, the flags in the arguments of `impactsph run`, the outcome.
  file(READ ${dir}/sweep_run.json record)
  string(JSON r_backend GET "${record}" backend)
  string(JSON r_precision GET "${record}" precision)
  string(JSON r_status GET "${record}" status)
  string(JSON p_backend GET "${record}" parameters backend)
  string(JSON p_precision GET "${record}" parameters precision)
  if(NOT r_backend STREQUAL backend OR NOT r_precision STREQUAL precision OR NOT p_backend STREQUAL backend OR
     NOT p_precision STREQUAL precision OR NOT r_status STREQUAL status)
    message(FATAL_ERROR "${run}: sweep_run.json records ${r_backend}/${r_precision} (parameters ${p_backend}/${p_precision}), status ${r_status}:\n${record}")
  endif()
  string(JSON nargs LENGTH "${record}" arguments)
  math(EXPR last "${nargs} - 1")
  set(args "")
  foreach(k RANGE ${last})
    string(JSON a GET "${record}" arguments ${k})
    list(APPEND args "${a}")
  endforeach()
  string(REPLACE ";" " " args "${args}")
  string(FIND "${args}" " --backend ${backend} --precision ${precision} --out ${dir} " at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${run}: the run was not given --backend ${backend} --precision ${precision}: ${args}")
  endif()
  # `impactsph run` wrote what it was asked for into run.json before it chose the solver.
  file(READ ${dir}/run.json runjson)
  string(JSON j_backend GET "${runjson}" backend)
  string(JSON j_precision GET "${runjson}" precision)
  if(NOT j_backend STREQUAL backend OR NOT j_precision STREQUAL precision)
    message(FATAL_ERROR "${run}: run.json has ${j_backend}/${j_precision}")
  endif()

  if(status STREQUAL "done")
    # The solver that ran names itself in summary.json: the backend and precision asked for.
    file(READ ${dir}/summary.json summary)
    string(JSON name GET "${summary}" solver)
    string(JSON completed GET "${summary}" completed)
    string(FIND "${name}" "${solver}" at)
    if(NOT at EQUAL 0 OR NOT completed)
      message(FATAL_ERROR "${run}: summary.json solver '${name}' (completed ${completed}), expected '${solver}...'")
    endif()
    if(NOT rows MATCHES "${run},1 mm,${backend},${precision},done,900,[0-9]+,")
      message(FATAL_ERROR "sweep.csv lacks the complete row of ${run}:\n${rows}")
    endif()
    message(STATUS "${run}: ${name}")
  else()
    string(JSON error GET "${record}" error)
    if(NOT error MATCHES "the reference solver runs in double only" OR NOT rows MATCHES "${run},1 mm,${backend},${precision},failed,")
      message(FATAL_ERROR "${run}: should fail with the run command's refusal of float: ${error}\n${rows}")
    endif()
  endif()
endforeach()

# Again: the three complete runs are the same runs (same case, backend and precision) and are skipped.
execute_process(COMMAND ${EXE} sweep ${SWEEP} --out ${OUT} --jobs 1 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 3 OR NOT out MATCHES "3 complete already, 0 to run")
  message(FATAL_ERROR "the second sweep should skip the complete runs (${rc}):\n${out}\n${err}")
endif()

# The Slurm array passes the same flags to each task.
execute_process(COMMAND ${EXE} sweep ${SWEEP} --out ${OUT}-slurm --emit slurm RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sweep --emit slurm failed (${rc}):\n${out}\n${err}")
endif()
file(READ ${OUT}-slurm/sweep.slurm script)
foreach(e ${expect})
  string(REPLACE "|" ";" e "${e}")
  list(GET e 0 backend)
  list(GET e 1 precision)
  string(FIND "${script}" " --backend ${backend} --precision ${precision} --out ${OUT}-slurm/spacing-1mm__backend-${backend}__precision-${precision} " at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sweep.slurm lacks the task of ${backend}/${precision}:\n${script}")
  endif()
endforeach()
