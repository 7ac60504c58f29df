# Kill-and-resume: a run killed midway (execute_process TIMEOUT kills the child) leaves some but not
# all blocks in OUT/checkpoint; `--resume OUT` runs only the missing realizations and ends with
# files identical to an uninterrupted run's (apart from the "# command:" and "# run_id:" lines). A
# resume with a contradicting --set exits 2 naming it and the key's two values.
# With -DMPIEXEC="mpirun;...;-np;2" the resume runs under MPI (the checkpoint is the same).
# Usage: cmake -DBINARY=... -DWORK=dir [-DMPIEXEC=...] -P run_resume.cmake
set(realizations 400)  # ≈ 1.7 s on 2 idle cores (2026-11-24): the first kills land midway
set(block_size 2)
math(EXPR block_count "${realizations} / ${block_size}")
set(scene --set t_max=200 --realizations ${realizations} --set block_size=${block_size})
file(REMOVE_RECURSE ${WORK})

execute_process(COMMAND ${BINARY} md run ${scene} --threads 2 --out ${WORK}/reference
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "reference run failed (${code}):\n${err}")
endif()
if(EXISTS ${WORK}/reference/checkpoint)
  message(FATAL_ERROR "a finished run left its checkpoint behind")
endif()

# Kill after 0.2 s; a loaded machine may not have finished a block yet, so wait longer then. (With
# a first kill at 1 s, 200 realizations finished before it on an idle machine: 0.84 s.)
foreach(seconds 0.2 0.4 0.8 1.6 3.2 6.4 12.8)
  execute_process(COMMAND ${BINARY} md run ${scene} --threads 2 --out ${WORK}/killed
                  TIMEOUT ${seconds} RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
  file(GLOB saved ${WORK}/killed/checkpoint/block_*.txt)
  list(LENGTH saved saved_count)
  message(STATUS "killed after ${seconds} s (${code}): ${saved_count} of ${block_count} blocks saved")
  if(saved_count GREATER 0)
    break()
  endif()
endforeach()
if(saved_count EQUAL 0 OR NOT saved_count LESS block_count OR EXISTS ${WORK}/killed/observables.csv)
  message(FATAL_ERROR "expected an interrupted run with some but not all of ${block_count} blocks saved, "
                      "found ${saved_count} (exit ${code})")
endif()

execute_process(COMMAND ${BINARY} md run ${scene} --set t_max=100 --resume ${WORK}/killed
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "--set t_max=100 contradicts the checkpoint in .*: t_max = 200 there, 100 now")
  message(FATAL_ERROR "resume with another t_max: exit ${code}, expected 2 naming t_max\n${out}${err}")
endif()

execute_process(COMMAND ${MPIEXEC} ${BINARY} md run ${scene} --threads 2 --resume ${WORK}/killed
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "resume failed (${code}):\n${out}\n${err}")
endif()
math(EXPR missing "${realizations} - ${saved_count} * ${block_size}")
if(NOT err MATCHES "md run: ${missing}/${missing} realizations")
  message(FATAL_ERROR "the resumed run should have run ${missing} realizations:\n${err}")
endif()
# The cost figures count only the work of the resumed process: the loaded blocks are reported apart.
math(EXPR loaded "${saved_count} * ${block_size}")
file(READ ${WORK}/killed/summary.json summary)
string(JSON resumed GET "${summary}" resumed_realizations)
string(JSON resumed_collisions GET "${summary}" resumed_collisions)
string(JSON collisions GET "${summary}" collisions_total)
file(READ ${WORK}/reference/summary.json reference_summary)
string(JSON reference_resumed GET "${reference_summary}" resumed_realizations)
if(NOT resumed EQUAL loaded OR NOT reference_resumed EQUAL 0 OR NOT resumed_collisions GREATER 0
   OR NOT resumed_collisions LESS collisions)
  message(FATAL_ERROR "summary.json: resumed_realizations ${resumed} (expected ${loaded}), reference ${reference_resumed} "
                      "(expected 0), resumed_collisions ${resumed_collisions} of ${collisions}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
coldblast_expect_same_outputs(${WORK}/reference ${WORK}/killed "the resumed run differs from the uninterrupted run's")
message(STATUS "resumed ${missing} of ${realizations} realizations; outputs identical")
