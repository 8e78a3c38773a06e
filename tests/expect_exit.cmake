# Runs COMMAND (a ';'-list) and checks its exit code is CODE and its standard error holds EXPECT:
# a test of a failure that checks both what CTest's PASS_REGULAR_EXPRESSION alone cannot (that
# option passes on the text whatever the exit code).
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL CODE)
  message(FATAL_ERROR "expected exit code ${CODE}, got ${code}: ${err}")
endif()
string(FIND "${err}" "${EXPECT}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "standard error does not hold '${EXPECT}': ${err}")
endif()
message(STATUS "exit ${code} as expected: ${err}")
