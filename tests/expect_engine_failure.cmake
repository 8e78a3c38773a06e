# Runs `springcheck run SCENE --engine ENGINE --engines-file FILE --out OUT` for an external engine
# that misbehaves and checks it is refused: exit code 4, a message naming the engine, and no
# output directory (nothing half-written).
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${EXE}" run "${SCENE}" --duration 0.2 --engine "${ENGINE}"
                        --engines-file "${ENGINES_FILE}" --out "${OUT}"
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL 4)
  message(FATAL_ERROR "expected exit code 4, got ${code}: ${err}")
endif()
string(FIND "${err}" "engine '${ENGINE}'" named)
if(named EQUAL -1)
  message(FATAL_ERROR "message does not name the engine: ${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "output written for a failed engine: ${OUT}")
endif()
message(STATUS "refused as expected: ${err}")
