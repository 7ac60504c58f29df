# Shared by the CLI script tests: the four files an `md run` writes must be identical in two output
# directories, line by line, apart from the "# command:" provenance line.
function(coldblast_expect_same_outputs dir_a dir_b what)
  foreach(file observables.csv blocks.csv accumulators.csv block_totals.csv)
    file(STRINGS ${dir_a}/${file} lines_a)
    file(STRINGS ${dir_b}/${file} lines_b)
    list(FILTER lines_a EXCLUDE REGEX "^# command: ")
    list(FILTER lines_b EXCLUDE REGEX "^# command: ")
    if(NOT lines_a STREQUAL lines_b)
      message(FATAL_ERROR "${file} of ${what}")
    endif()
  endforeach()
endfunction()
