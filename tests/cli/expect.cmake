# expect(WHAT CODE REGEX COMMAND...): runs COMMAND and fails the script unless it exits with CODE and
# its stdout+stderr match REGEX; logs the exit. Included by the CLI's cmake -P test scripts, with
# stop_midway.
function(expect what code regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE got OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT got STREQUAL "${code}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "${what}: exit ${got} (expected ${code}), output should match '${regex}'\n"
                        "stdout:\n${out}\nstderr:\n${err}")
  endif()
  message(STATUS "${what}: exit ${got}")
endfunction()
# Runs `BINARY ARGN --out folder`, killed after each of `timeouts` seconds in turn, until a run is
# stopped with some blocks saved and no outputs written; sets `variable` to the saved blocks.
function(stop_midway folder timeouts variable)
  foreach(seconds ${timeouts})
    file(REMOVE_RECURSE ${folder})
    execute_process(COMMAND ${BINARY} ${ARGN} --out ${folder} TIMEOUT ${seconds} OUTPUT_QUIET ERROR_QUIET)
    file(GLOB saved ${folder}/checkpoint/block_*.txt)
    list(LENGTH saved saved_count)
    if(saved_count GREATER 0 AND NOT EXISTS ${folder}/manifest.json)
      set(${variable} ${saved_count} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "expected a stopped run in ${folder} with some blocks saved, found ${saved_count}")
endfunction()
