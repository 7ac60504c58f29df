# MPI tracer (COLDBLAST_MPI=ON): `mpirun -np 2 coldblast tracer` runs through md's one MPI launcher
# (md::run_blocks_mpi) and writes, on rank 0 only, the files of the single-process 2-thread run of
# the same seed, line by line apart from the "# command:" line (md's files, p_imp.csv, moments.csv,
# prefactors.csv, the tracer's sums) and the same tracer summary keys; summary.json records 2 ranks.
# Bad input ends every rank with exit 2 naming the option.
# Usage: cmake -DBINARY=... -DMPIEXEC="mpirun;--allow-run-as-root;--oversubscribe;-np;2" -DWORK=dir -P run_tracer_mpi.cmake
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
file(REMOVE_RECURSE ${WORK})
foreach(background tvns ns)
  # 32 blocks of 2 trajectories: both ranks take blocks.
  set(run tracer --background ${background} --set t_max=50 --trajectories 64 --set block_size=2 --seed 7)
  coldblast_run_threads_and_ranks("${run}" ${WORK}/${background}/threads ${WORK}/${background}/ranks
                                  "collision rate")
  coldblast_expect_same_tracer_outputs(${WORK}/${background}/threads ${WORK}/${background}/ranks
                                       "mpirun -np 2 tracer (${background}) differs from the threaded run's"
                                       "${coldblast_tracer_summary_keys}")
endforeach()
execute_process(COMMAND ${MPIEXEC} ${BINARY} tracer --background plasma --out ${WORK}/bad
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "--background = plasma is not one of")
  message(FATAL_ERROR "bad --background under mpirun: exit ${code}, expected 2 naming --background\n${out}${err}")
endif()
message(STATUS "mpirun -np 2 tracer: outputs identical to --threads 2")
