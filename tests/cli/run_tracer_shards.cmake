# The tracer's ensembles use md's shard/merge machinery (one launcher, md::run_slots_in_parallel and
# the run-directory format): `coldblast tracer --shard 0/2` and `--shard 1/2` merged with
# `coldblast md merge` give the files of one 2-thread run, line by line apart from the "# command:"
# provenance line (the merge keeps the shards' A_d source and region).
# Usage: cmake -DBINARY=... -DWORK=dir -P run_tracer_shards.cmake
set(run tracer --background tvns --set t_max=50 --trajectories 64)
file(REMOVE_RECURSE ${WORK})
foreach(args "--threads;2;--out;${WORK}/all" "--shard;0/2;--out;${WORK}/s0" "--shard;1/2;--out;${WORK}/s1")
  execute_process(COMMAND ${BINARY} ${run} ${args} RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "tracer ${args} failed (${code}):\n${err}")
  endif()
endforeach()
execute_process(COMMAND ${BINARY} md merge ${WORK}/s0 ${WORK}/s1 --out ${WORK}/merged
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "md merge of the tracer shards failed (${code}):\n${err}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
coldblast_expect_same_outputs(${WORK}/all ${WORK}/merged "the merged tracer shards differs from the single run's")
file(STRINGS ${WORK}/all/p_imp.csv lines_a REGEX "^[^#]")
file(STRINGS ${WORK}/merged/p_imp.csv lines_b REGEX "^[^#]")
list(LENGTH lines_a count)
if(count LESS 10 OR NOT lines_a STREQUAL lines_b)
  message(FATAL_ERROR "p_imp.csv of the merged tracer shards differs from the single run's (${count} lines)")
endif()
message(STATUS "tracer --shard 0/2 + 1/2, md merge: identical to one run")
