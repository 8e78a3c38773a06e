# Runs COMMAND (a ';'-list) and checks its exit code is CODE and its standard error holds EXPECT:
# a test of a failure that checks both what CTest's PASS_REGULAR_EXPRESSION alone cannot (that
# option passes on the text whatever the exit code). Optional: WORKDIR, the folder to run it in;
# EXPECT_OUT, text standard output must hold; QUIET, standard error must be empty.
if(NOT DEFINED WORKDIR)
  set(WORKDIR .)
endif()
execute_process(COMMAND ${COMMAND} WORKING_DIRECTORY "${WORKDIR}" RESULT_VARIABLE code
                ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL CODE)
  message(FATAL_ERROR "expected exit code ${CODE}, got ${code}: ${err}")
endif()
if(DEFINED EXPECT)
  string(FIND "${err}" "${EXPECT}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "standard error does not hold '${EXPECT}': ${err}")
  endif()
endif()
if(DEFINED EXPECT_OUT)
  string(FIND "${out}" "${EXPECT_OUT}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "standard output does not hold '${EXPECT_OUT}': ${out}")
  endif()
endif()
if(QUIET AND NOT err STREQUAL "")
  message(FATAL_ERROR "expected nothing on standard error, got: ${err}")
endif()
message(STATUS "exit ${code} as expected: ${err}")
