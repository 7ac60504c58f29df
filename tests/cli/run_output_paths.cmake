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

include(${CMAKE_CURRENT_LIST_DIR}/expect.cmake)

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

# Output folders (--out of compare, md run, tracer, hydro; common::require_output_folder and
# compare::report_folder): anything but a folder or a new path exits 2 naming --out before any work,
# and is left as it was; a compare report replaces only a new, empty or previous report's folder, and
# through a symlink it fills the link's folder while the link stays a link.
set(fixture ${CMAKE_CURRENT_LIST_DIR}/data/run_T0_wrong)
file(MAKE_DIRECTORY ${WORK}/folders/user)
file(WRITE ${WORK}/folders/user/mine.txt "precious\n")
file(WRITE ${WORK}/folders/file "precious\n")
file(CREATE_LINK nowhere ${WORK}/folders/dangling SYMBOLIC)
execute_process(COMMAND mkfifo ${WORK}/folders/fifo)
set(kinds "fifo=a FIFO" "file=a regular file" "dangling=a symlink to nothing")
execute_process(COMMAND mknod ${WORK}/folders/device c 1 3 RESULT_VARIABLE no_device ERROR_QUIET)  # root only
if(no_device EQUAL 0)
  list(APPEND kinds "device=a character device")
endif()
foreach(entry IN LISTS kinds)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 kind)
  set(path ${WORK}/folders/${name})
  expect("compare --out ${name}" 2 "--out = ${path} is ${kind}" ${BINARY} compare ${fixture} --no-figures --out ${path})
  expect("tracer --out ${name}" 2 "--out = ${path} is ${kind}" ${BINARY} tracer --trajectories 4 --out ${path})
  expect("md run --out ${name}" 2 "--out = ${path} is ${kind}" ${BINARY} md run --set t_max=5 --out ${path})
  expect("hydro core --out ${name}" 2 "--out = ${path} is ${kind}" ${BINARY} hydro core --until 30 --out ${path})
  expect("reproduce --out ${name}" 2 "--out = ${path} is ${kind}" ${BINARY} reproduce --out ${path})
endforeach()
file(MAKE_DIRECTORY ${WORK}/folders/reproduce/report-paper)
file(WRITE ${WORK}/folders/reproduce/report-paper/mine.txt "precious\n")
expect("reproduce into a folder whose report-paper holds other files" 2
       "--out = ${WORK}/folders/reproduce/report-paper holds mine.txt" ${BINARY} reproduce --out ${WORK}/folders/reproduce)
expect("compare --out a folder of other files" 2 "--out = ${WORK}/folders/user holds mine.txt, which is not part of a compare report"
       ${BINARY} compare ${fixture} --no-figures --out ${WORK}/folders/user)
expect("md run --out under a file" 2 "--out = ${WORK}/folders/file/run cannot be created: ${WORK}/folders/file is a regular file"
       ${BINARY} md run --set t_max=5 --out ${WORK}/folders/file/run)
file(READ ${WORK}/folders/file file_text)
file(READ ${WORK}/folders/user/mine.txt user_text)
file(GLOB reproduce_entries RELATIVE ${WORK}/folders/reproduce ${WORK}/folders/reproduce/*)
if(NOT reproduce_entries STREQUAL "report-paper")  # refused before step 1: nothing written
  message(FATAL_ERROR "reproduce wrote before refusing its folder: ${reproduce_entries}")
endif()
execute_process(COMMAND test -p ${WORK}/folders/fifo RESULT_VARIABLE fifo_kept)
execute_process(COMMAND sh -c "test ${no_device} -ne 0 || test -c '${WORK}/folders/device'" RESULT_VARIABLE device_kept)
if(NOT file_text STREQUAL "precious\n" OR NOT user_text STREQUAL "precious\n" OR NOT fifo_kept EQUAL 0
   OR NOT device_kept EQUAL 0 OR NOT IS_SYMLINK ${WORK}/folders/dangling OR EXISTS ${WORK}/folders/nowhere)
  message(FATAL_ERROR "an output path given to --out was replaced or changed")
endif()
file(MAKE_DIRECTORY ${WORK}/folders/empty)
file(CREATE_LINK empty ${WORK}/folders/report-link SYMBOLIC)
foreach(round first second)  # the second replaces the first report through the link
  expect("compare --out a symlink to a folder (${round})" 3 "wrote 3 files to ${WORK}/folders/report-link"
         ${BINARY} compare ${fixture} --no-figures --out ${WORK}/folders/report-link)
endforeach()
if(NOT IS_SYMLINK ${WORK}/folders/report-link OR NOT EXISTS ${WORK}/folders/empty/verdict.json)
  message(FATAL_ERROR "the report replaced the symlink instead of filling its folder")
endif()
