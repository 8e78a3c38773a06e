# Runs `springcheck run SCENE --out OUT` and checks it is refused with no output directory
# (nothing half-written). A bad scene: exit code 2 and a message naming the scene file. With
# ENGINE and ENGINES_FILE, an external engine that misbehaves: exit code 4 and a message naming
# the engine.
file(REMOVE_RECURSE "${OUT}")
set(args run "${SCENE}" --out "${OUT}")
set(expected_code 2)
set(expected_name "${SCENE}")
if(DEFINED EXTRA)  # more arguments (a ';'-list) and the text the message must hold
  list(APPEND args ${EXTRA})
  set(expected_name "${EXPECT}")
endif()
if(DEFINED ENGINE)
  list(APPEND args --duration 0.2 --engine "${ENGINE}" --engines-file "${ENGINES_FILE}")
  set(expected_code 4)
  set(expected_name "engine '${ENGINE}'")
endif()
execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out)
if(NOT code EQUAL expected_code)
  message(FATAL_ERROR "expected exit code ${expected_code}, got ${code}: ${err}")
endif()
string(FIND "${err}" "${expected_name}" named)
if(named EQUAL -1)
  message(FATAL_ERROR "message does not name ${expected_name}: ${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "output written for a refused run: ${OUT}")
endif()
message(STATUS "refused as expected: ${err}")
