# Runs `springcheck run SCENE --out OUT` and checks it is refused: exit code 2, a message that
# names the scene file, and no output directory.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${EXE}" run "${SCENE}" --out "${OUT}"
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "expected exit code 2, got ${code}: ${err}")
endif()
string(FIND "${err}" "${SCENE}" named)
if(named EQUAL -1)
  message(FATAL_ERROR "message does not name the file: ${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "output written for a refused scene: ${OUT}")
endif()
message(STATUS "refused as expected: ${err}")
