# The tracer in an MD run's own measured fields (`tracer --background md --md-run DIR`, issue 32) as a
# user runs it: an `md run` recording profiles and R, the tracer in its fields with the MD's scene
# (no SCENE given), summary.json naming the MD run (path and run id), `compare TRACER --md-run MD`;
# shards merged with `md merge` equal one run; a stopped run resumes from its folder alone to the
# same files, and refuses another --md-run (exit 2 naming it and both folders).
# Usage: cmake -DBINARY=... -DWORK=dir -P run_tracer_md.cmake
include(${CMAKE_CURRENT_LIST_DIR}/expect_same_outputs.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)
file(REMOVE_RECURSE ${WORK})

set(md md run --set t_max=50 --set realizations=16 --set block_size=2 --threads 2
       --set "observables=[\"R_imp\",\"V_imp\",\"C_imp\",\"R\",\"profiles\",\"p_imp\"]")
expect("md run with profiles" 0 "collisions" ${BINARY} ${md} --out ${WORK}/md)
expect("another md run" 0 "collisions" ${BINARY} ${md} --set realizations=12 --out ${WORK}/md-other)
file(READ ${WORK}/md/manifest.json manifest)
string(JSON md_id GET "${manifest}" run_id)

set(tracer tracer --background md --md-run ${WORK}/md --trajectories 20000 --set block_size=40)
expect("tracer in the md run's fields" 0 "tracer \\(md background\\), scene default \\(d = 2\\): 20000 trajectories"
       ${BINARY} ${tracer} --threads 2 --out ${WORK}/reference)
file(READ ${WORK}/reference/summary.json summary)
string(JSON recorded_id GET "${summary}" md_run_id)
string(JSON recorded_path GET "${summary}" md_run)
string(JSON description GET "${summary}" background_description)
if(NOT recorded_id STREQUAL md_id OR NOT recorded_path STREQUAL "${WORK}/md"
   OR NOT description MATCHES "^MD profiles: 30 bins of r/R from 0 to 1.5, 23 recorded times t from 1 to 45.25, ")
  message(FATAL_ERROR "summary.json: md_run_id '${recorded_id}' (the MD's is ${md_id}), md_run '${recorded_path}', "
                      "background_description '${description}'")
endif()
expect("compare the tracer against the md run" 0 "tracer in this MD run.s own fields against the MD run .*C_imp" ${BINARY} compare
       ${WORK}/reference --md-run ${WORK}/md --sigma 10 --allowance 1 --no-figures --no-report)
expect("compare the tracer against another md run" 0 "tracer in the fields of MD run ${md_id} against the MD run .*md-other"
       ${BINARY} compare ${WORK}/reference --md-run ${WORK}/md-other --sigma 10 --allowance 1 --no-figures --no-report)

set(keys ${coldblast_tracer_summary_keys} md_run md_run_id)
foreach(shard 0 1)
  expect("tracer shard ${shard}/2" 0 "collision rate" ${BINARY} ${tracer} --shard ${shard}/2 --out ${WORK}/s${shard})
endforeach()
expect("md merge of the shards" 0 "collision rate" ${BINARY} md merge ${WORK}/s0 ${WORK}/s1 --out ${WORK}/merged)
coldblast_expect_same_tracer_outputs(${WORK}/reference ${WORK}/merged "the merged md-background shards" "${keys}")
string(REPLACE "${WORK}/md;" "${WORK}/md-other;" other_tracer "${tracer}")
expect("tracer shard 1/2 in another md run's fields" 0 "collision rate" ${BINARY} ${other_tracer} --shard 1/2
       --out ${WORK}/other-s1)
expect("md merge of shards in two md runs' fields" 2 "ran a different tracer.*md_run" ${BINARY} md merge ${WORK}/s0
       ${WORK}/other-s1 --out ${WORK}/bad)

stop_midway(${WORK}/stopped "0.3;0.6;1.2;2.4;4.8;9.6;19.2" saved_count ${tracer} --threads 2)
message(STATUS "stopped with ${saved_count} blocks saved")
expect("tracer --resume with another md run" 2
       "--md-run = ${WORK}/md-other contradicts the checkpoint in .*, which has --md-run = ${WORK}/md;"
       ${BINARY} tracer --background md --md-run ${WORK}/md-other --resume ${WORK}/stopped)
expect("tracer --resume DIR alone" 0 "collision rate" ${BINARY} tracer --resume ${WORK}/stopped)
coldblast_expect_same_tracer_outputs(${WORK}/reference ${WORK}/stopped "the md-background tracer resumed" "${keys}")
message(STATUS "tracer --background md: run, compare, shards merged, stopped and resumed")
