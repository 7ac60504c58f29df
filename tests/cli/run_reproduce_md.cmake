# `coldblast reproduce` runs its MD step as `coldblast md run` of the paper scene would: the same
# amplitude A_2(phi) sizes the box (hydro::md_amplitude), the same seed and block size, so
# the two give the same per-realization values to the last digit and `md run` + `reproduce
# --md-run` is the paper-scale reproduce in two resumable steps (docs/verification.md, Campaign 1).
# Only the commented provenance headers differ (command line, where A_d came from). Likewise its
# tracer step is `coldblast tracer` of the paper scene in the dense NS background, seed 1.
# Usage: cmake -DBINARY=... -DSCENE=scenes/paper-2d.toml -DWORK=dir -P run_reproduce_md.cmake
file(REMOVE_RECURSE ${WORK})
execute_process(COMMAND ${BINARY} reproduce --realizations 4 --hydro-until 50 --tracer-trajectories 600 --threads 2 --no-figures --out ${WORK}/reproduce
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0 AND NOT code EQUAL 3)  # 3: a failed verdict, expected with 4 realizations
  message(FATAL_ERROR "reproduce failed (${code}):\n${err}")
endif()
# reproduce's block size is max(1, realizations / 64) = 1, its seed 1
execute_process(COMMAND ${BINARY} md run ${SCENE} --realizations 4 --set block_size=1 --seed 1 --threads 2 --out ${WORK}/md
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "md run failed (${code}):\n${err}")
endif()
foreach(file observables.csv blocks.csv)
  file(STRINGS ${WORK}/reproduce/md/${file} lines_a)
  file(STRINGS ${WORK}/md/${file} lines_b)
  list(FILTER lines_a EXCLUDE REGEX "^#")
  list(FILTER lines_b EXCLUDE REGEX "^#")
  list(LENGTH lines_a count)
  if(count LESS 10)
    message(FATAL_ERROR "${file}: only ${count} data lines")
  endif()
  if(NOT lines_a STREQUAL lines_b)
    message(FATAL_ERROR "${file} of reproduce's MD step differs from md run's")
  endif()
endforeach()
execute_process(COMMAND ${BINARY} tracer ${SCENE} --background ns --transport enskog --trajectories 600 --seed 1 --threads 1 --out ${WORK}/tracer
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "tracer failed (${code}):\n${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
coldblast_expect_same_tracer_outputs(${WORK}/reproduce/tracer ${WORK}/tracer "reproduce's tracer step differs from coldblast tracer's"
                                     "trajectories;collision_rate;collision_rate_error;chi;temperature_final;rejection_rate;background_description")
