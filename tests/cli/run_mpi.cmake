# MPI ensembles (COLDBLAST_MPI=ON): `mpirun -np 2 coldblast md run` writes observables.csv,
# blocks.csv, accumulators.csv and block_totals.csv byte-identical (apart from the "# command:"
# line) to the 2-thread single-process run of the same scene and seed; ranks > 0 write nothing.
# Usage: cmake -DBINARY=... -DMPIEXEC="mpirun;--allow-run-as-root;--oversubscribe;-np;2" -DWORK=dir -P run_mpi.cmake
set(scene md run --set t_max=50 --realizations 32 --set block_size=2 --seed 5)
file(REMOVE_RECURSE ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
coldblast_run_threads_and_ranks("${scene}" ${WORK}/threads ${WORK}/ranks "scene default")
coldblast_expect_same_outputs(${WORK}/threads ${WORK}/ranks "mpirun -np 2 differs from the threaded run's")

# A bad scene value ends every rank with exit 2 naming the key.
execute_process(COMMAND ${MPIEXEC} ${BINARY} md run --set n=-1 --out ${WORK}/bad
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "n = -1 is outside")
  message(FATAL_ERROR "bad n under mpirun: exit ${code}, expected 2 naming n\n${out}${err}")
endif()
# Each rank's message is one write: the lines of two ranks do not interleave mid-line.
if(err MATCHES "coldblast: error: [^\n]*coldblast: error: ")
  message(FATAL_ERROR "the ranks' error lines interleave:\n${err}")
endif()
# A runtime failure ends every rank with exit 1 (no hang) and no output files. A_d = 10 (45 times
# the true A_2) puts Eq. (1)'s R(t_max) far inside the real shock, which reaches the guard at t ≈ 400
# in both realizations, one per rank (rank 1's is the path where a worker reports to rank 0); the
# regex accepts either rank's message. (A_d = 0.1 at t_max = 200 tripped only through the early
# phase, which the region now holds: md::early_reach_bound.)
execute_process(COMMAND ${MPIEXEC} ${BINARY} md run --set box_margin=1.25 --set region_growths=0 --set A_d=10 --set t_max=1000 --seed 2
                        --realizations 2 --set block_size=1 --out ${WORK}/failed
                TIMEOUT 120 RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 1 OR NOT err MATCHES "coldblast: failed: (rank 1: )?a moving particle.*raise region_growths \\(now 0\\) or box_margin"
   OR EXISTS ${WORK}/failed/observables.csv)
  message(FATAL_ERROR "guard trip under mpirun: exit ${code}, expected 1 naming box_margin\n${out}${err}")
endif()
message(STATUS "mpirun -np 2: outputs identical to --threads 2; errors end every rank")
