# The tracer's ensembles use the run layer's shard/merge machinery (one launcher, run::run_slots_in_parallel and
# the run-directory format): `coldblast tracer --shard 0/2` and `--shard 1/2` merged with
# `coldblast md merge` give the files of one 2-thread run, line by line apart from the "# command:"
# provenance line (the merge keeps the shards' A_d source and region), moments.csv, prefactors.csv
# and the tracer's summary keys included; for the equilibrium background also T and
# collision_rate_exact. A shard of a different tracer run is refused (exit 2 naming the key).
# Usage: cmake -DBINARY=... -DWORK=dir -P run_tracer_shards.cmake
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
file(REMOVE_RECURSE ${WORK})
foreach(case tvns equilibrium)
  if(case STREQUAL "tvns")
    set(run tracer --background tvns --set t_max=50 --trajectories 64)
    set(keys ${coldblast_tracer_summary_keys})
  else()
    set(run tracer --background equilibrium --T 2 --phi 0.2 --transport enskog --set t_max=20 --trajectories 96
            --set block_size=8)
    set(keys ${coldblast_tracer_summary_keys} T collision_rate_exact)
  endif()
  foreach(args "--threads;2;--out;${WORK}/${case}/all" "--shard;0/2;--out;${WORK}/${case}/s0"
          "--shard;1/2;--out;${WORK}/${case}/s1")
    execute_process(COMMAND ${BINARY} ${run} ${args} RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
      message(FATAL_ERROR "tracer ${args} failed (${code}):\n${err}")
    endif()
  endforeach()
  execute_process(COMMAND ${BINARY} md merge ${WORK}/${case}/s0 ${WORK}/${case}/s1 --out ${WORK}/${case}/merged
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT out MATCHES "collision rate")
    message(FATAL_ERROR "md merge of the tracer shards failed (${code}) or printed no tracer summary:\n${out}${err}")
  endif()
  coldblast_expect_same_tracer_outputs(${WORK}/${case}/all ${WORK}/${case}/merged
                                       "the merged ${case} tracer shards differs from the single run's" "${keys}")
endforeach()
# Shard 1 of another bath temperature is another run: exit 2 naming the differing key.
execute_process(COMMAND ${BINARY} tracer --background equilibrium --T 3 --phi 0.2 --transport enskog --set t_max=20
                        --trajectories 96 --set block_size=8 --shard 1/2 --out ${WORK}/other
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
execute_process(COMMAND ${BINARY} md merge ${WORK}/equilibrium/s0 ${WORK}/other --out ${WORK}/bad
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "ran a different tracer.*(T = 3|background_description)")
  message(FATAL_ERROR "md merge of two tracer runs: exit ${code}, expected 2 naming the key\n${out}${err}")
endif()
message(STATUS "tracer --shard 0/2 + 1/2, md merge: identical to one run (tvns and equilibrium)")
