# Shared by the command-line tests that read a generated report.md: every expected text is in it, and it
# names no absolute path of the machine (the run's output folder OUT).
function(expect_report report out)
  foreach(expect ${ARGN})
    string(FIND "${report}" "${expect}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "report.md lacks '${expect}':\n${report}")
    endif()
  endforeach()
  string(FIND "${report}" "${out}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "report.md names the absolute path ${out}:\n${report}")
  endif()
endfunction()
