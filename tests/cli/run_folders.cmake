# One run per folder (issue 29), as a user meets it on the command line:
# - a second `md run` into a folder holding a finished run exits 2 naming --out and changes nothing;
#   with --overwrite it replaces exactly the old run's files (a user's file stays);
# - a folder mixing two runs' files is refused by compare and md merge, naming the file;
# - the same command on a folder holding a stopped run's checkpoint exits 2 saying how to resume,
#   and deletes no saved block; `--resume DIR` alone finishes it with the files of an
#   uninterrupted run; an option given again that contradicts the checkpoint exits 2 naming it and
#   both values;
# - the same for `coldblast tracer`.
# Usage: cmake -DBINARY=... -DWORK=dir -P run_folders.cmake
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
file(REMOVE_RECURSE ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
function(manifest_run_id folder variable)
  file(READ ${folder}/manifest.json manifest)
  string(JSON id GET "${manifest}" run_id)
  set(${variable} ${id} PARENT_SCOPE)
endfunction()

# A finished run, then the same folder again.
set(small md run --set t_max=20 --set block_size=1)
expect("first run" 0 "collisions" ${BINARY} ${small} --realizations 2 --set "observables=[\"R_imp\",\"snapshots\"]"
       --set "snapshot_times=[10.0]" --out ${WORK}/x)
manifest_run_id(${WORK}/x first)
expect("a second run into the folder" 2 "--out = ${WORK}/x holds the files of run ${first} .*--overwrite"
       ${BINARY} ${small} --realizations 3 --out ${WORK}/x)
manifest_run_id(${WORK}/x still)
if(NOT still STREQUAL first OR NOT EXISTS ${WORK}/x/snapshot_10.csv)
  message(FATAL_ERROR "the refused run changed the folder")
endif()
file(WRITE ${WORK}/x/notes.txt "mine\n")
expect("--overwrite" 0 "collisions" ${BINARY} ${small} --realizations 3 --out ${WORK}/x --overwrite)
manifest_run_id(${WORK}/x second)
if(second STREQUAL first OR EXISTS ${WORK}/x/snapshot_10.csv OR EXISTS ${WORK}/x/snapshots.extxyz
   OR NOT EXISTS ${WORK}/x/notes.txt)
  message(FATAL_ERROR "--overwrite must remove exactly the first run's files (snapshots gone, notes.txt kept)")
endif()

# A folder holding two runs' files: every reader refuses it, naming the file.
expect("another run" 0 "collisions" ${BINARY} ${small} --realizations 2 --set t_max=30 --out ${WORK}/y)
file(COPY_FILE ${WORK}/y/observables.csv ${WORK}/x/observables.csv)
expect("compare of a mixed folder" 2 "RUN_DIR: ${WORK}/x/observables.csv belongs to run .*mixes the files of different runs"
       ${BINARY} compare ${WORK}/x --no-figures)
expect("md merge of a mixed folder" 2 "md merge DIR: ${WORK}/x/observables.csv belongs to run"
       ${BINARY} md merge ${WORK}/x --out ${WORK}/merged)

# A stopped run: the same command refuses, --resume alone continues, contradictions are named.
set(scene md run --set t_max=200 --realizations 400 --set block_size=2 --threads 2)
expect("reference run" 0 "collisions" ${BINARY} ${scene} --out ${WORK}/reference)
stop_midway(${WORK}/stopped "0.2;0.4;0.8;1.6;3.2;6.4;12.8" saved_count ${scene})
expect("the same command again" 2
       "--out = ${WORK}/stopped holds the checkpoint of an unfinished run \\(${saved_count} blocks? saved in .*\\): continue it with `coldblast md run --resume ${WORK}/stopped`, or start anew with --overwrite"
       ${BINARY} ${scene} --out ${WORK}/stopped)
file(GLOB still_saved ${WORK}/stopped/checkpoint/block_*.txt)
list(LENGTH still_saved still_count)
if(NOT still_count EQUAL saved_count)
  message(FATAL_ERROR "the refused run changed the checkpoint (${saved_count} then ${still_count} blocks)")
endif()
expect("--resume with another t_max" 2 "--set t_max=100 contradicts the checkpoint in .*: t_max = 200 there, 100 now"
       ${BINARY} md run --set t_max=100 --resume ${WORK}/stopped)
expect("--resume with other realizations" 2 "--realizations = 7 contradicts the checkpoint in .*, which has 400"
       ${BINARY} md run --realizations 7 --resume ${WORK}/stopped)
expect("--resume with another shard" 2 "--shard = 1/2 contradicts the checkpoint in .*, which runs shard 0/1"
       ${BINARY} md run --shard 1/2 --resume ${WORK}/stopped)
expect("--resume DIR alone" 0 "collisions" ${BINARY} md run --resume ${WORK}/stopped --threads 2)
coldblast_expect_same_outputs(${WORK}/reference ${WORK}/stopped "the run resumed from its folder alone")
if(EXISTS ${WORK}/stopped/checkpoint)
  message(FATAL_ERROR "the finished run left its checkpoint")
endif()

# The same for the tracer.
set(tracer tracer --background tvns --set t_max=400 --trajectories 40000 --set block_size=40 --threads 2)
expect("tracer reference" 0 "collision rate" ${BINARY} ${tracer} --out ${WORK}/tracer-reference)
stop_midway(${WORK}/tracer "0.3;0.6;1.2;2.4;4.8;9.6;19.2" saved_count ${tracer})
expect("tracer: the same command again" 2 "continue it with `coldblast tracer --resume ${WORK}/tracer`"
       ${BINARY} ${tracer} --out ${WORK}/tracer)
expect("tracer: --resume with another background" 2
       "--background = ns contradicts the checkpoint in .*, which has --background = tvns"
       ${BINARY} tracer --background ns --resume ${WORK}/tracer)
expect("tracer: --resume with another scene" 2 "--set contradicts the checkpoint in .*: E = 10 there, 11 now"
       ${BINARY} tracer --set E=11 --resume ${WORK}/tracer)
expect("tracer: --resume DIR alone" 0 "collision rate" ${BINARY} tracer --resume ${WORK}/tracer)
coldblast_expect_same_tracer_outputs(${WORK}/tracer-reference ${WORK}/tracer "the tracer resumed from its folder alone"
                                     "${coldblast_tracer_summary_keys}")
message(STATUS "one run per folder: refused, overwritten, mixed folders refused, stopped runs resumed from their folder")
