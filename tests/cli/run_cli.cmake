# Usage: cmake -DBINARY=... -DARGS="a;b;c" -DEXPECTED_CODE=N -DEXPECTED_REGEX=... -P run_cli.cmake
# Checks the exit code exactly and searches the regex in stdout+stderr.
execute_process(COMMAND ${BINARY} ${ARGS}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT code STREQUAL "${EXPECTED_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECTED_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT "${EXPECTED_REGEX}" STREQUAL "" AND NOT all MATCHES "${EXPECTED_REGEX}")
  message(FATAL_ERROR "output does not match '${EXPECTED_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
