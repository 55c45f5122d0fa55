# `impactsph verify --suite smoke` (the elastic wave at 2, 1 and 0.8 mm, about 20 s on one core): the
# report, its tables, the fitted order, results.csv and the two PNGs. The figures themselves are checked
# by the analytic tests; here the velocity-profile error must fall with the spacing (a positive order).
# Needs gnuplot. -DEXE=... -DOUT=...
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} verify --suite smoke --threads 1 --out ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph verify failed (${rc}):\n${out}\n${err}")
endif()
foreach(f report.md results.csv convergence.png convergence.gp speed_vs_error.png speed_vs_error.gp)
  if(NOT EXISTS ${OUT}/${f})
    message(FATAL_ERROR "verify did not write ${f}")
  endif()
endforeach()
file(READ ${OUT}/report.md report)
foreach(expect "| CPU | " "| threads per run | 1 " "| git commit (at the start) | " "| date | 20"
        "## Skipped\n" "![error against spacing](convergence.png)")
  string(FIND "${report}" "${expect}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report.md lacks '${expect}':\n${report}")
  endif()
endforeach()
if(NOT report MATCHES "\n\\| elastic wave: velocity profile L1 \\| ([0-9]+\\.[0-9]+) \\| [0-9.]+ \\| 3 \\|\n")
  message(FATAL_ERROR "report.md has no positive fitted order of the velocity-profile error over 3 points:\n${report}")
endif()
message(STATUS "observed order of the velocity-profile L1 error at 2, 1, 0.8 mm: ${CMAKE_MATCH_1}")
string(REGEX MATCHALL "\n\\| elastic wave: velocity profile L1 \\| [0-9.]+ \\| [-+]" rows "${report}")
list(LENGTH rows n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "report.md should list 3 velocity-profile errors, has ${n}:\n${report}")
endif()
file(STRINGS ${OUT}/results.csv csv)
list(LENGTH csv lines)
if(NOT lines EQUAL 10)  # header + 3 spacings x 3 measures
  message(FATAL_ERROR "results.csv should have 10 lines, has ${lines}")
endif()
