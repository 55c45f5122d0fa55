# `impactsph sweep --emit slurm` and `--collect` on tests/data/sweeps/taylor_table.toml (two Taylor bar
# runs of a few steps): the job-array script's content, one array task run by hand as Slurm would
# (SLURM_ARRAY_TASK_ID=0), the collect step's table, and a local sweep that skips the run the array did.
# -DEXE=... -DSWEEP=... -DOUT=...
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} sweep ${SWEEP} --out ${OUT} --emit slurm --threads-per-run 2
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sweep --emit slurm failed (${rc}):\n${out}\n${err}")
endif()
file(READ ${OUT}/sweep.slurm script)
foreach(expect "#SBATCH --array=0-1\n" "#SBATCH --cpus-per-task=2\n" "#SBATCH --time=00:05:00\n" "#SBATCH --mem=1G\n"
        "#SBATCH --output=${OUT}/slurm-%A_%a.out\n" "export OMP_NUM_THREADS=2\n"
        "  0)\n    DIR=${OUT}/spacing-2.5mm\n    ARGS=(run "
        " --spacing '2.5 mm' --set output.vtu=false --set 'time.end=5 us' --set 'time.frame_interval=5 us' --out ${OUT}/spacing-2.5mm --threads 2 --quiet)\n"
        "  1)\n    DIR=${OUT}/spacing-2mm\n"
        "    RESTART=(run --restart ${OUT}/spacing-2mm --threads 2 --quiet)\n"
        "exec \"$IMPACTSPH\" \"\${RESTART[@]}\"" "exec \"$IMPACTSPH\" \"\${ARGS[@]}\"")
  string(FIND "${script}" "${expect}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sweep.slurm lacks '${expect}':\n${script}")
  endif()
endforeach()
string(REGEX MATCHALL "\n  [0-9]+\\)\n" tasks "${script}")
list(LENGTH tasks n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "sweep.slurm should have 2 array tasks, has ${n}")
endif()
file(READ ${OUT}/collect.slurm collect)
if(NOT collect MATCHES "sweep [^\n]*taylor_table.toml --out ${OUT} --collect\n")
  message(FATAL_ERROR "collect.slurm does not build the table:\n${collect}")
endif()
file(READ ${OUT}/submit.sh submit)
if(NOT submit MATCHES "sbatch --parsable sweep.slurm" OR NOT submit MATCHES "--dependency=afterany:[^ ]+ collect.slurm")
  message(FATAL_ERROR "submit.sh does not chain the collect step after the array:\n${submit}")
endif()

# Array task 0 as Slurm would run it, then the collect step: one run done, one not run (exit 3).
# Passive OpenMP waits: two spinning threads on a CI machine shared with other tests crawl.
execute_process(COMMAND ${CMAKE_COMMAND} -E env SLURM_ARRAY_TASK_ID=0 IMPACTSPH=${EXE} OMP_WAIT_POLICY=PASSIVE
                        bash ${OUT}/sweep.slurm
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/spacing-2.5mm/summary.json)
  message(FATAL_ERROR "array task 0 failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env IMPACTSPH=${EXE} bash ${OUT}/collect.slurm
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 3 OR NOT out MATCHES "1 of 2 runs complete")
  message(FATAL_ERROR "collect with one run missing should say so and exit 3 (${rc}):\n${out}\n${err}")
endif()

# A local sweep finishes the other run only; the table carries the bar's observables from summary.json.
execute_process(COMMAND ${EXE} sweep ${SWEEP} --out ${OUT} --jobs 1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "1 complete already, 1 to run")
  message(FATAL_ERROR "the local sweep did not skip the run the array did (${rc}):\n${out}\n${err}")
endif()
file(STRINGS ${OUT}/sweep.csv rows)
list(GET rows 0 head)
if(NOT head STREQUAL "run,spacing,status,particles,steps,wall_time_s,particle_steps_per_s,mean_neighbours,energy_drift,correction_fallbacks,final_length_m,impact_face_diameter_m,impact_face_diameter_area_m,impact_face_diameter_shifted_m")
  message(FATAL_ERROR "unexpected sweep.csv header: ${head}")
endif()
foreach(run spacing-2.5mm spacing-2mm)
  file(READ ${OUT}/${run}/summary.json summary)
  string(JSON length GET "${summary}" observables final_length)
  string(JSON particles GET "${summary}" particles)
  string(JSON steps GET "${summary}" steps)
  # The CSV keeps 6 significant digits of the value in summary.json.
  execute_process(COMMAND printf "%.6g" ${length} OUTPUT_VARIABLE length6)
  list(FILTER rows INCLUDE REGEX "^${run},")
  set(all_rows ${rows})
  file(STRINGS ${OUT}/sweep.csv rows)
  if(NOT all_rows MATCHES "^${run},[0-9.]+ mm,done,${particles},${steps},[0-9.e+-]+,[0-9.e+-]+,[0-9.]+,[-0-9.e]+,[0-9]+,${length6},[0-9.e-]+,[0-9.e-]+,[0-9.e-]+$")
    message(FATAL_ERROR "sweep.csv row of ${run} does not match its summary.json (${particles} particles, ${steps} steps, final length ${length6}):\n${all_rows}")
  endif()
endforeach()
file(READ ${OUT}/sweep.md md)
if(NOT md MATCHES "\\| run \\| spacing \\| status \\| particles \\|" OR NOT md MATCHES "\n\\| spacing-2mm \\| 2 mm \\| done \\|")
  message(FATAL_ERROR "unexpected sweep.md:\n${md}")
endif()
