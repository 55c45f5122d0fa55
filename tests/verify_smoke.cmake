# `impactsph verify --suite smoke` (the elastic wave at 2, 1 and 0.8 mm with the reference, and at 2 mm
# with the gpu port beside it in double and float; about 20 s on one core): the report, its tables, the
# fitted order, results.csv, crosscheck.csv, the convergence chart, the speed-against-error chart of the
# elastic wave with its table and cheapest-run line, the picture of the finest run, and that the report
# names no absolute path. The figures themselves are checked by the
# analytic and crosscheck tests; here the velocity-profile error must fall with the spacing (a positive
# order), and the section "CPU against GPU port" must hold the tolerances of the crosscheck CTests:
# double fields within 1e-9, the float elastic-wave observables within 0.5 %. Needs gnuplot.
# -DEXE=... -DOUT=...
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} verify --suite smoke --threads 1 --out ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph verify failed (${rc}):\n${out}\n${err}")
endif()
foreach(f report.md results.csv crosscheck.csv convergence.png convergence.gp speed_error_elastic_wave.png
        speed_error_elastic_wave.gp picture_elastic_wave.png picture_elastic_wave.gp picture_elastic_wave.dat)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "verify did not write ${f}")
  endif()
endforeach()
file(READ ${OUT}/report.md report)
include(${CMAKE_CURRENT_LIST_DIR}/report_checks.cmake)
# The report names no folder of this machine: the program by its name, the output folder relative.
expect_report("${report}" "${OUT}" "| CPU | " "| threads per run | 1 " "| git commit (at the start) | " "| date | 20"
        "## Skipped\n" "![error against spacing](convergence.png)" "## CPU against GPU port\n"
        "## Speed against error, per case\n"
        "![Elastic wave (cases/elastic-wave-convergence): wall time against error](speed_error_elastic_wave.png)"
        "![elastic wave at 0.8 mm](picture_elastic_wave.png)"
        "Written by `impactsph verify --suite smoke --threads 1 --out ")
if(NOT report MATCHES "\n\\| elastic wave: velocity profile L1 \\| ([0-9]+\\.[0-9]+) \\| [0-9.]+ \\| 3 \\|\n")
  message(FATAL_ERROR "report.md has no positive fitted order of the velocity-profile error over 3 points:\n${report}")
endif()
message(STATUS "observed order of the velocity-profile L1 error at 2, 1, 0.8 mm: ${CMAKE_MATCH_1}")
foreach(solver_count "reference, double|3" "gpu port [a-zA-Z ]+, double|1" "gpu port [a-zA-Z ]+, float|1")
  string(REPLACE "|" ";" solver_count "${solver_count}")
  list(GET solver_count 0 solver)
  list(GET solver_count 1 count)
  string(REGEX MATCHALL "\n\\| elastic wave: velocity profile L1 \\| ${solver} \\| [0-9.]+ \\| [-+]" rows "${report}")
  list(LENGTH rows n)
  if(NOT n EQUAL count)
    message(FATAL_ERROR "report.md should list ${count} velocity-profile errors of '${solver}', has ${n}:\n${report}")
  endif()
endforeach()
# Speed against error: one row per run (3 reference spacings, the port in double and float at 2 mm), and
# the cheapest run within the analytic tests' targets, which every run meets: one at 2 mm, the cheapest
# spacing by far.
string(REGEX MATCHALL "\n\\| (2|1|0\\.8) \\| (reference|gpu port [a-zA-Z ]+), (double|float) \\| [-+][0-9.]+ % \\| [-+][0-9.]+ % \\| [-+][0-9.]+ % \\|[^\n]*\\| yes \\|"
       runs "${report}")
list(LENGTH runs n)
if(NOT n EQUAL 5)
  message(FATAL_ERROR "the elastic wave's speed-against-error table should have 5 runs within the targets, has ${n}:\n${report}")
endif()
if(NOT report MATCHES "\n- \\*\\*Elastic wave\\*\\*: the cheapest run within 1 % \\(wave speed\\) and 3 % \\(stress amplitude\\) of the closed form is spacing 2 mm on the (reference|gpu port [a-zA-Z ]+) \\((double|float)\\), ([0-9.e+-]+) s on this machine")
  message(FATAL_ERROR "report.md has no cheapest-run line of the elastic wave at 2 mm:\n${report}")
endif()
message(STATUS "cheapest elastic-wave run within the targets: 2 mm, ${CMAKE_MATCH_1} (${CMAKE_MATCH_2}), ${CMAKE_MATCH_3} s")
file(STRINGS ${OUT}/results.csv csv)
list(LENGTH csv lines)
if(NOT lines EQUAL 16)  # header + (3 reference spacings + 2 gpu-port runs at 2 mm) x 3 measures
  message(FATAL_ERROR "results.csv should have 16 lines, has ${lines}")
endif()
foreach(bp "reference,double" "gpu,double" "gpu,float")
  string(REGEX MATCHALL "\"elastic wave: wave speed\",0.002,[^;]*,${bp}(;|$)" hits "${csv}")
  list(LENGTH hits n)
  if(NOT n EQUAL 1)
    message(FATAL_ERROR "results.csv should have the wave-speed error at 2 mm of ${bp} once, has ${n}")
  endif()
endforeach()

# CPU against GPU port: the port names its build, the field differences at the end, the observables and
# the speed ratio of the same run.
if(NOT report MATCHES "The gpu port ran as `gpu port \\(double, (host OpenMP build|CUDA)\\)`, `gpu port \\(float, (host OpenMP build|CUDA)\\)`")
  message(FATAL_ERROR "report.md does not say which build of the gpu port ran:\n${report}")
endif()
set(num "[0-9.]+e[-+][0-9]+")
foreach(precision double float)
  if(NOT report MATCHES "\n\\| elastic wave \\| 2 \\| 200 \\| [0-9]+ \\| 10 \\| ${precision} \\| (${num}) / (${num}) \\| (${num}) / (${num}) \\| (${num}) / (${num}) \\| (${num}) / (${num}) \\| (${num}) \\|\n")
    message(FATAL_ERROR "report.md has no field-difference row of the ${precision} port at 2 mm:\n${report}")
  endif()
  set(diffs ${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3} ${CMAKE_MATCH_4} ${CMAKE_MATCH_5} ${CMAKE_MATCH_6}
            ${CMAKE_MATCH_7} ${CMAKE_MATCH_8})
  message(STATUS "gpu port ${precision} against the reference at 2 mm, displacement/velocity/density/stress L2, max: ${diffs}")
  if(precision STREQUAL "double")
    foreach(d ${diffs})  # crosscheck.double_elastic_wave: --field-tol 1e-9
      if(NOT d LESS 1e-9)
        message(FATAL_ERROR "the double port differs from the reference by ${d} (> 1e-9):\n${report}")
      endif()
    endforeach()
  endif()
  if(NOT report MATCHES "\n\\| 2 \\| gpu port, ${precision} \\| [0-9.]+ \\| [-+](${num}) \\| [0-9.]+ \\| [-+](${num}) \\|")
    message(FATAL_ERROR "report.md has no elastic-wave observables of the ${precision} port:\n${report}")
  endif()
  foreach(d ${CMAKE_MATCH_1} ${CMAKE_MATCH_2})  # crosscheck.float_elastic_wave: --wave-tol 5e-3
    if(NOT d LESS 5e-3)
      message(FATAL_ERROR "the ${precision} port's wave speed or stress amplitude differs by ${d} (> 0.5 %):\n${report}")
    endif()
  endforeach()
  if(NOT report MATCHES "\n\\| elastic wave \\| 2 \\| [0-9.e+]+ \\| [0-9.]+ \\| [0-9.e+]+ \\| ${precision} \\| [0-9.]+ \\| [0-9.e+]+ \\| ([0-9.]+) \\|\n")
    message(FATAL_ERROR "report.md has no speed row of the ${precision} port:\n${report}")
  endif()
  message(STATUS "speed ratio reference/gpu port ${precision} at 2 mm: ${CMAKE_MATCH_1}")
endforeach()
file(STRINGS ${OUT}/crosscheck.csv cc)
list(LENGTH cc lines)
if(NOT lines EQUAL 4)  # header + reference, gpu double, gpu float
  message(FATAL_ERROR "crosscheck.csv should have 4 lines, has ${lines}")
endif()
