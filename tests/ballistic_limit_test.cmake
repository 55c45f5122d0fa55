# `impactsph ballistic-limit` end to end on the 8 mm plate at a coarse spacing and a short end time
# (about 20 s on two cores): 50 m/s must stop and 600 m/s perforate by 40 us, so the search runs both
# ends and two rounds of two. Checks the result lines, ballistic.csv, ballistic.json, the PNG and
# report.md with the pictures of the key runs (the fastest, 600 m/s, among them).
# Needs gnuplot (Debian: gnuplot-nox, installed by scripts/impactsph.sh).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} ballistic-limit ${CASE} --from 50 --to 600 --tolerance 100 --jobs 2
                        --spacing 2.5mm --set time.end=40us --set output.vtu=false --out ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "impactsph ballistic-limit failed (${rc}):\n${out}\n${err}")
endif()
# One progress line per run: speed, verdict, residual velocity, wall time.
if(NOT out MATCHES "\n +50 m/s +no +-?[0-9.]+ m/s +[0-9.]+ s" OR NOT out MATCHES "\n +600 m/s +yes +[0-9.]+ m/s +[0-9.]+ s")
  message(FATAL_ERROR "no progress lines for the two ends:\n${out}")
endif()
if(NOT out MATCHES "\nballistic limit: [0-9]+\\.[0-9] m/s\nrecht-ipson: a = [0-9.]+, p = [0-9.]+ \\(v_bl fixed at [0-9.]+ m/s\\), rms residual [0-9.]+ m/s")
  message(FATAL_ERROR "unexpected result lines:\n${out}")
endif()
# The 8 mm case folder has reference.csv: the reference p = 2 form is evaluated.
if(NOT out MATCHES "reference: p = 2, a = m_p/\\(m_p \\+ m_plug\\) = [0-9.]+ g/\\([0-9.]+ g \\+ [0-9.]+ g\\) = 0\\.909")
  message(FATAL_ERROR "no reference p = 2 line:\n${out}")
endif()

file(STRINGS ${OUT}/ballistic.csv csv)
list(LENGTH csv lines)
list(GET csv 0 header)
if(NOT header STREQUAL "v_impact_m_s,perforated,residual_velocity_m_s,plug_velocity_m_s,plug_mass_kg,settled_time_s,wall_s")
  message(FATAL_ERROR "ballistic.csv header: ${header}")
endif()
if(lines LESS 5)  # header + both ends + at least one round of two
  message(FATAL_ERROR "ballistic.csv has ${lines} lines:\n${csv}")
endif()
list(GET csv 1 first)
if(NOT first MATCHES "^50,0,")
  message(FATAL_ERROR "ballistic.csv does not start with the non-perforating 50 m/s run: ${first}")
endif()

file(READ ${OUT}/ballistic.json json)
foreach(key limit_m_s bracket_m_s a p runs recht_ipson reference)
  string(JSON value ERROR_VARIABLE json_err GET "${json}" ${key})
  if(json_err OR value STREQUAL "null")
    message(FATAL_ERROR "ballistic.json lacks ${key}: ${json_err}")
  endif()
endforeach()

if(NOT EXISTS ${OUT}/ballistic_curve.png)
  message(FATAL_ERROR "no ballistic_curve.png:\n${out}\n${err}")
endif()
file(READ ${OUT}/ballistic_curve.png magic LIMIT 8 HEX)
if(NOT magic STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "ballistic_curve.png is not a PNG (starts ${magic})")
endif()
foreach(v 50 600)
  if(NOT EXISTS ${OUT}/v_${v}/summary.json)
    message(FATAL_ERROR "the run at ${v} m/s left no v_${v}/summary.json")
  endif()
endforeach()
file(READ ${OUT}/report.md report)
include(${CMAKE_CURRENT_LIST_DIR}/report_checks.cmake)
expect_report("${report}" "${OUT}" "# Ballistic limit: plate-8mm\n" "Written by `impactsph ballistic-limit "
              "| ballistic limit | " "![residual velocity against impact velocity](ballistic_curve.png)"
              "### 600 m/s: the fastest run\n\n![600 m/s at its end](v_600/picture.png)")
if(NOT EXISTS ${OUT}/v_600/picture.png OR EXISTS ${OUT}/v_50/picture.png AND NOT report MATCHES "v_50/picture.png")
  message(FATAL_ERROR "the pictures drawn do not match the key runs of report.md")
endif()
file(GLOB leftovers ${OUT}/*.tmp-* ${OUT}/v_*/*.tmp-*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()

# A wrong end that had not settled by time.end: the message says so and how to continue that run (the
# high end, 60 m/s, is still slowing in the plate at 20 us).
file(REMOVE_RECURSE ${OUT}-wrong-end)
execute_process(COMMAND ${EXE} ballistic-limit ${CASE} --from 50 --to 60 --tolerance 5 --jobs 2
                        --spacing 2.5mm --set time.end=20us --set output.vtu=false --out ${OUT}-wrong-end
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 4 OR NOT err MATCHES "error: the high end is wrong: --to 60 m/s does not perforate 'plate'"
   OR NOT err MATCHES "It had not settled by time.end = 20 us, so its verdict may still change: continue it with `impactsph run --restart [^`]*v_60 --end 30us`")
  message(FATAL_ERROR "expected the wrong-end message with the continue hint (exit 4), got ${rc}:\n${out}\n${err}")
endif()
file(REMOVE_RECURSE ${OUT}-wrong-end)
