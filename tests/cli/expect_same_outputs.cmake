# Shared by the CLI script tests: the four files an `md run` writes must be identical in two output
# directories, line by line, apart from the "# command:" and "# run_id:" provenance lines (two runs).
function(coldblast_expect_same_outputs dir_a dir_b what)
  foreach(file observables.csv blocks.csv accumulators.csv block_totals.csv)
    file(STRINGS ${dir_a}/${file} lines_a)
    file(STRINGS ${dir_b}/${file} lines_b)
    list(FILTER lines_a EXCLUDE REGEX "^# (command|run_id): ")
    list(FILTER lines_b EXCLUDE REGEX "^# (command|run_id): ")
    if(NOT lines_a STREQUAL lines_b)
      message(FATAL_ERROR "${file} of ${what}")
    endif()
  endforeach()
endfunction()

# A tracer run directory: md's four files and p_imp.csv, the tracer's moments.csv, prefactors.csv
# and exact sums (tracer_blocks.csv, moment_sums.csv) line by line (apart from "# command:"), and
# summary.json's tracer keys value by value (`keys`: the keys to compare).
function(coldblast_expect_same_tracer_outputs dir_a dir_b what keys)
  coldblast_expect_same_outputs(${dir_a} ${dir_b} "${what}")
  foreach(file p_imp.csv moments.csv prefactors.csv tracer_blocks.csv moment_sums.csv)
    file(STRINGS ${dir_a}/${file} lines_a)
    file(STRINGS ${dir_b}/${file} lines_b)
    list(FILTER lines_a EXCLUDE REGEX "^# (command|run_id): ")
    list(FILTER lines_b EXCLUDE REGEX "^# (command|run_id): ")
    list(LENGTH lines_a count)
    if(count LESS 10 OR NOT lines_a STREQUAL lines_b)
      message(FATAL_ERROR "${file} of ${what} (${count} lines)")
    endif()
  endforeach()
  file(READ ${dir_a}/summary.json summary_a)
  file(READ ${dir_b}/summary.json summary_b)
  foreach(key ${keys})
    string(JSON value_a ERROR_VARIABLE error_a GET "${summary_a}" ${key})
    string(JSON value_b ERROR_VARIABLE error_b GET "${summary_b}" ${key})
    if(error_a OR error_b OR NOT value_a STREQUAL value_b)
      message(FATAL_ERROR "summary.json key ${key} of ${what}: '${value_a}' against '${value_b}' ${error_a}${error_b}")
    endif()
  endforeach()
endfunction()

# The tracer's summary keys that do not depend on how the blocks were spread (not the wall time).
set(coldblast_tracer_summary_keys
    trajectories collision_rate collision_rate_error chi n_ambient temperature_final temperature_final_error
    candidates_total rejection_rate background background_description background_frames transport start
    start_time impurity_mass impurity_radius realizations collisions_total blocks engine)

# One MPI launch checked against the threaded run: `BINARY run_args --threads 2 --out threads_dir`
# and `MPIEXEC BINARY run_args --out ranks_dir` must both exit 0, mpirun's stdout must hold exactly
# one summary (rank 0 only; `summary_regex` marks it), and ranks_dir/summary.json must record 2 ranks.
# The caller then compares the two directories' files.
function(coldblast_run_threads_and_ranks run_args threads_dir ranks_dir summary_regex)
  execute_process(COMMAND ${BINARY} ${run_args} --threads 2 --out ${threads_dir}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "threaded run failed (${code}):\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${MPIEXEC} ${BINARY} ${run_args} --out ${ranks_dir}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "mpirun run failed (${code}):\n${out}\n${err}")
  endif()
  string(REGEX MATCHALL "${summary_regex}" summaries "${out}")
  list(LENGTH summaries summary_count)
  if(NOT summary_count EQUAL 1)
    message(FATAL_ERROR "expected one summary (rank 0 only), found ${summary_count}:\n${out}")
  endif()
  file(READ ${ranks_dir}/summary.json summary)
  if(NOT summary MATCHES "\"ranks\": 2")
    message(FATAL_ERROR "summary.json does not record 2 ranks:\n${summary}")
  endif()
endfunction()
