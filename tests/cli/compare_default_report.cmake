# compare writes its report beside the run by default (RUN_DIR/compare-<against>/), with every
# figure as PNG and PDF and the kept gnuplot scripts; a repeat replaces that report; --no-report
# writes nothing; --out and --no-report together exit 2 naming both. Exit codes checked.
# Usage: cmake -DBINARY=... -DFIXTURE=run_dir -DWORK=dir -P compare_default_report.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(COPY ${FIXTURE}/ DESTINATION ${WORK}/run)

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

function(require_files)
  foreach(file IN LISTS ARGN)
    if(NOT EXISTS ${file})
      message(FATAL_ERROR "missing ${file}")
    endif()
  endforeach()
endfunction()

set(report ${WORK}/run/compare-theory)
expect("compare without --out" 3 "verdict: FAIL.*compare: wrote [0-9]+ files to .*run/compare-theory"
       ${BINARY} compare ${WORK}/run)
require_files(${report}/report.md ${report}/verdict.json ${report}/exponents.csv ${report}/figures/observables.gp
              ${report}/figures/observables.png ${report}/figures/observables.pdf)
file(READ ${report}/figures/observables.pdf head LIMIT 5)
if(NOT head MATCHES "^%PDF-")
  message(FATAL_ERROR "observables.pdf is not a PDF: '${head}'")
endif()
# the stdout stays the summary: no file list on stdout
execute_process(COMMAND ${BINARY} compare ${WORK}/run --against paper RESULT_VARIABLE got OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(out MATCHES "wrote" OR NOT err MATCHES "wrote [0-9]+ files to .*run/compare-paper" OR NOT got STREQUAL "3")
  message(FATAL_ERROR "compare --against paper: exit ${got}\nstdout:\n${out}\nstderr:\n${err}")
endif()
require_files(${WORK}/run/compare-paper/verdict.json)
# A repeat replaces the report it wrote.
file(WRITE ${report}/figures/stale.dat "from an earlier report\n")
expect("compare repeated" 3 "wrote [0-9]+ files to .*run/compare-theory" ${BINARY} compare ${WORK}/run)
if(EXISTS ${report}/figures/stale.dat)
  message(FATAL_ERROR "the repeated report kept a file of the old one")
endif()
# --no-report writes nothing; --out with --no-report is refused.
file(REMOVE_RECURSE ${report} ${WORK}/run/compare-paper)
expect("compare --no-report" 3 "verdict: FAIL" ${BINARY} compare ${WORK}/run --no-report)
file(GLOB written ${WORK}/run/compare-*)
if(written)
  message(FATAL_ERROR "--no-report wrote ${written}")
endif()
expect("compare --out with --no-report" 2 "--no-report excludes --out|--out excludes --no-report"
       ${BINARY} compare ${WORK}/run --no-report --out ${WORK}/x)
