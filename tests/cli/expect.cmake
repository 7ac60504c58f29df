# expect(WHAT CODE REGEX COMMAND...): runs COMMAND and fails the script unless it exits with CODE and
# its stdout+stderr match REGEX; logs the exit. Included by the CLI's cmake -P test scripts.
function(expect what code regex)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE got OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT got STREQUAL "${code}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "${what}: exit ${got} (expected ${code}), output should match '${regex}'\n"
                        "stdout:\n${out}\nstderr:\n${err}")
  endif()
  message(STATUS "${what}: exit ${got}")
endfunction()
