# The output path rules (common/output.hpp) as a user meets them, exit codes checked:
# /dev/full exits 1 naming the path and stays a device; /dev/null, "-", /dev/stdout, a FIFO and a
# symlink are written (the link stays a link); stdout on /dev/full or closed exits 1 with a message;
# a reader that leaves a pipe early (| head -c 10) ends the run quietly by SIGPIPE (141), or with
# exit 1 and a message when the caller ignores SIGPIPE.
# (No ';' inside the shell commands: expect() receives them through a CMake list.)
# Usage: cmake -DBINARY=... -DWORK=dir -P run_output_paths.cmake
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(profile tvns --points 3 --profile)

function(expect what code regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE got OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT got STREQUAL "${code}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "${what}: exit ${got} (expected ${code}), output should match '${regex}'\n"
                        "stdout:\n${out}\nstderr:\n${err}")
  endif()
  message(STATUS "${what}: exit ${got}")
endfunction()

expect("--profile /dev/full" 1 "coldblast: failed: cannot write /dev/full: No space left on device" ${BINARY} ${profile} /dev/full)
execute_process(COMMAND test -c /dev/full RESULT_VARIABLE is_device)
file(GLOB left_behind /dev/full.tmp*)
if(NOT is_device EQUAL 0 OR left_behind)
  message(FATAL_ERROR "/dev/full is no longer a character device, or temporaries were left: ${left_behind}")
endif()
expect("--profile /dev/null" 0 "wrote /dev/null" ${BINARY} ${profile} /dev/null)
expect("--profile -" 0 "r_over_R,density.*\n1,2.99999" ${BINARY} ${profile} -)
expect("--profile /dev/stdout" 0 "r_over_R,density.*\n1,2.99999" ${BINARY} ${profile} /dev/stdout)

file(MAKE_DIRECTORY ${WORK}/scratch)
file(WRITE ${WORK}/scratch/profile.csv "old\n")
file(CREATE_LINK scratch/profile.csv ${WORK}/link.csv SYMBOLIC)
expect("--profile through a symlink" 0 "wrote" ${BINARY} ${profile} ${WORK}/link.csv)
file(READ ${WORK}/scratch/profile.csv written)
if(NOT IS_SYMLINK ${WORK}/link.csv OR NOT written MATCHES "^# program: coldblast")
  message(FATAL_ERROR "the symlink was replaced or its target not written:\n${written}")
endif()

execute_process(COMMAND mkfifo ${WORK}/fifo)
expect("--profile FIFO" 0 "r_over_R,density"
       sh -c "cat '${WORK}/fifo' & '${BINARY}' tvns --points 3 --profile '${WORK}/fifo' >/dev/null
wait")
execute_process(COMMAND test -p ${WORK}/fifo RESULT_VARIABLE is_fifo)
if(NOT is_fifo EQUAL 0)
  message(FATAL_ERROR "the FIFO was replaced")
endif()

# An output smaller than stdio's buffer (4 KiB) fails in the exit check's flush; a large one (3 MB)
# fails in a write part-way through the run, whose errno the checked stdout keeps for the exit check
# (common::check_standard_output_writes): both name the reason, and only once.
expect("stdout on /dev/full" 1 "cannot write standard output: No space left on device"
       sh -c "'${BINARY}' theory --d 1 --format json > /dev/full")
expect("3 MB of stdout on /dev/full" 1 "^coldblast: error: cannot write standard output: No space left on device\n$"
       sh -c "'${BINARY}' theory --d-range 2..1001 --format json > /dev/full")
expect("180 kB of table on /dev/full" 1 "^coldblast: error: cannot write standard output: No space left on device\n$"
       sh -c "'${BINARY}' theory --d-range 2..1001 > /dev/full")
expect("stdout closed" 1 "cannot write standard output: Bad file descriptor" sh -c "'${BINARY}' theory >&-")
expect("stdout to a reader that leaves" 0 "^141\n$"
       bash -c "'${BINARY}' theory --d-range 2..1001 --format json | head -c 10 >/dev/null
echo \${PIPESTATUS[0]}")
expect("... with SIGPIPE ignored" 0 "^1\ncoldblast: error: cannot write standard output: "
       bash -c "trap '' PIPE
'${BINARY}' theory --d-range 2..1001 --format json | head -c 10 >/dev/null
echo \${PIPESTATUS[0]}")
