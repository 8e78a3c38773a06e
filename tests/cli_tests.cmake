# The tests that run the springcheck executable or a script around it (tests/CMakeLists.txt
# holds the test binaries): refusals of bad input, the commands' outputs, the tooling (install,
# package, Slurm, report, main job) and the code's own checks. Included by tests/CMakeLists.txt.
# Overrides that would overflow the step count or never end: refused, naming the field.
foreach(case IN ITEMS "dt_subnormal|--dt;1e-320|integrator.dt"
                      "duration_infinite|--duration;inf|--duration: expected a finite number"
                      "duration_huge|--duration;1e300|at most 1e+09"
                      "duration_below_the_step|--duration;0.01|integrator.dt: a step no longer")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 flag)
  list(GET parts 2 value)
  list(GET parts 3 expect)
  add_test(NAME cli_refuses_override_${name}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:springcheck>
                   -DSCENE=${PROJECT_SOURCE_DIR}/scenes/seed/circle.json "-DEXTRA=${flag}\;${value}"
                   "-DEXPECT=${expect}" -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out_override_${name}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_refused.cmake)
  set_tests_properties(cli_refuses_override_${name} PROPERTIES LABELS "validation;cli")
endforeach()

# External engines that misbehave: exit 4, the engine named, nothing written.
foreach(mode IN ITEMS exit-code timeout wrong-shape particle-count nan short wrong-times missing-file)
  add_test(NAME cli_refuses_external_engine_${mode}
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:springcheck>
                   -DSCENE=${PROJECT_SOURCE_DIR}/scenes/matched/chain_hanging.json -DENGINE=${mode}
                   -DENGINES_FILE=${CMAKE_CURRENT_SOURCE_DIR}/data/misbehaving_engines.json
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/cli_out_engine_${mode}
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_refused.cmake)
  set_tests_properties(cli_refuses_external_engine_${mode} PROPERTIES LABELS "validation;cli")
endforeach()

# Every command lists the registry's engines, a user's own included.
if(SPRINGCHECK_PYTHON)
  add_test(NAME every_command_lists_the_same_engines
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/engines_listed_test.sh $<TARGET_FILE:springcheck>
                   ${SPRINGCHECK_PYTHON} ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/engines_listed)
  # Every seed scene runs in mysim and both deformable Bullet engines, refused by none.
  add_test(NAME suite_runs_every_seed_scene_in_mysim_and_bullet
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/seed_suite_test.sh $<TARGET_FILE:springcheck>
                   ${SPRINGCHECK_PYTHON} ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/seed_suite)
  # Killed mid-run or mid-write, stability, compare and sweep leave whole result files.
  add_test(NAME interrupted_runs_leave_whole_result_files
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/interrupted_writes_test.sh $<TARGET_FILE:springcheck>
                   ${SPRINGCHECK_PYTHON} ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/interrupted)
  # What an external engine starts ends with its run; SIGINT and SIGTERM stop it cleanly.
  add_test(NAME external_engines_leave_no_process_behind
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/process_boundary_test.sh $<TARGET_FILE:springcheck>
                   ${PROJECT_SOURCE_DIR}/scenes/matched/chain_hanging.json
                   ${CMAKE_CURRENT_SOURCE_DIR}/data)
  set_tests_properties(external_engines_leave_no_process_behind PROPERTIES LABELS "external;cli")
  # Two runs into one --out at once leave one of them whole; a folder of the user's is refused.
  add_test(NAME result_folders_hold_one_whole_run
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/whole_folders_test.sh $<TARGET_FILE:springcheck>
                   ${PROJECT_SOURCE_DIR}/scenes/matched/chain_hanging.json)
  set_tests_properties(result_folders_hold_one_whole_run PROPERTIES LABELS cli)
  # gate --json to a path it cannot write: an error and a non-zero exit, not silence. One
  # passing check (the circle's) is enough: exit 1 then comes from the write alone.
  add_test(NAME gate_json_to_an_unwritable_path_fails
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;gate;--tolerances;${CMAKE_CURRENT_SOURCE_DIR}/data/report_tolerances.json;--json;/nonexistent/folder/gate.json"
                   -DCODE=1 "-DEXPECT=error: --json: cannot write /nonexistent/folder/gate.json"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties(every_command_lists_the_same_engines PROPERTIES LABELS "cli;external")
  # slow: whole runs of every seed scene in three engines (138 s under the sanitizers); there the
  # seed scenes' steps run in every engine in ShippedSceneOpening and the suite command in
  # suite_gate_failure_is_not_hidden_by_a_blowup.
  set_tests_properties(suite_runs_every_seed_scene_in_mysim_and_bullet PROPERTIES
                       LABELS "cli;bullet;slow")
  # slow: what it checks is where bytes land when a process is killed, not C++ memory use; two
  # minutes under the sanitizers, so the Release pass alone runs it.
  set_tests_properties(interrupted_runs_leave_whole_result_files PROPERTIES LABELS "cli;slow")
  set_tests_properties(gate_json_to_an_unwritable_path_fails PROPERTIES LABELS "cli;gate")
  # suite --tolerances: a failed check exits 1 even where a run blew up (3 would hide it).
  add_test(NAME suite_gate_failure_is_not_hidden_by_a_blowup
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;suite;${CMAKE_CURRENT_SOURCE_DIR}/data/blowing_chain;--out;${CMAKE_CURRENT_BINARY_DIR}/suite_gate_blowup;--tolerances;${CMAKE_CURRENT_SOURCE_DIR}/data/failing_circle_tolerances.json;--gate-json;${CMAKE_CURRENT_BINARY_DIR}/suite_gate_blowup.json"
                   -DCODE=1 "-DEXPECT_OUT=gate: 0 passed, 1 failed"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties(suite_gate_failure_is_not_hidden_by_a_blowup PROPERTIES LABELS "cli;gate")
  # suite --engines: a name no engine has is refused before any scene runs, naming the option.
  add_test(NAME suite_engines_refuses_an_unknown_engine_naming_the_option
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;suite;${CMAKE_CURRENT_SOURCE_DIR}/data/blowing_chain;--out;${CMAKE_CURRENT_BINARY_DIR}/suite_unknown_engine;--engines;mysim,nosuch"
                   -DCODE=2 "-DEXPECT=error: --engines: unknown engine 'nosuch'"
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties(suite_engines_refuses_an_unknown_engine_naming_the_option PROPERTIES LABELS "cli;validation")
  # A failing gate's JUnit XML and markdown: the failing check with its numbers.
  add_test(NAME gate_junit_lists_the_failing_check_with_its_numbers
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/gate_junit_test.sh $<TARGET_FILE:springcheck>
                   ${SPRINGCHECK_PYTHON} ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/gate_junit)
  set_tests_properties(gate_junit_lists_the_failing_check_with_its_numbers PROPERTIES LABELS "gate;cli")
  # The example external engine under its own gate (examples/external/tolerances.json).
  add_test(NAME gate_external_example
           COMMAND springcheck gate --tolerances ${PROJECT_SOURCE_DIR}/examples/external/tolerances.json)
  # slow: whole runs in the Python engine and mysim (41 s under the sanitizers, Python's time
  # mostly); the gate's and the external engine's C++ run there in gate_junit_..., suite_gate_...
  # and the external tests.
  set_tests_properties(gate_external_example PROPERTIES LABELS "gate;external;slow")
endif()

# The tolerance gates: every bound of compare/tolerances.json against mysim and Bullet. Where the
# main job's test runs (matplotlib found, below), the job's "suite and gate" stage checks these very
# bounds on the suite's runs and fails the test on any of them (59 s of the Release pass's CPU
# spent twice, issue 34); `springcheck gate --tolerances compare/tolerances.json` checks them alone.
if(NOT SPRINGCHECK_PYTHON)
  add_test(NAME gate COMMAND springcheck gate --tolerances ${PROJECT_SOURCE_DIR}/compare/tolerances.json)
  # slow: minutes under the sanitizers, where the gates' code is the studies' and metrics' the
  # unit and physics tests already run; the Release pass runs it (scripts/run-tests.sh).
  set_tests_properties(gate PROPERTIES LABELS "gate;bullet;physics;slow")
endif()

# compare given run's --integrator: refused, saying to name the integrator in --engines.
add_test(NAME compare_with_integrator_says_to_write_engines_mysim_integrator
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;compare;${PROJECT_SOURCE_DIR}/scenes/matched/cloth_hanging.json;--integrator;xpbd;--engines;mysim"
                 -DCODE=2 "-DEXPECT=write --engines mysim:xpbd"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
# list run from a folder with no scenes/ lists the scenes springcheck ships, with no error.
file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/list_elsewhere)
add_test(NAME list_from_another_folder_lists_the_shipped_scenes
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;list" -DCODE=0
                 -DWORKDIR=${CMAKE_CURRENT_BINARY_DIR}/list_elsewhere -DQUIET=ON
                 "-DEXPECT_OUT=matched/chain_hanging.json"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
set_tests_properties(compare_with_integrator_says_to_write_engines_mysim_integrator
                     list_from_another_folder_lists_the_shipped_scenes PROPERTIES LABELS cli)

# Bash completion: every subcommand and its options.
add_test(NAME completion_offers_every_subcommand_and_option
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/completion_test.sh $<TARGET_FILE:springcheck>)
set_tests_properties(completion_offers_every_subcommand_and_option PROPERTIES LABELS cli)

# The man page help2man made lists every subcommand the help does.
if(HELP2MAN)
  add_test(NAME man_page_lists_every_subcommand
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/man_page_test.sh $<TARGET_FILE:springcheck>
                   ${PROJECT_BINARY_DIR}/cli/springcheck.1)
  set_tests_properties(man_page_lists_every_subcommand PROPERTIES LABELS cli)
endif()

# springcheck --version: the project's version and the commit it was built from.
add_test(NAME version_names_the_release_and_the_commit COMMAND springcheck --version)
set_tests_properties(version_names_the_release_and_the_commit PROPERTIES LABELS cli
  PASS_REGULAR_EXPRESSION "^springcheck [0-9]+\\.[0-9]+\\.[0-9]+ \\(commit ([0-9a-f]+(-dirty)?|unknown)\\)")

# Installed into a temporary prefix: runs and reports from an unrelated folder, and a consumer
# project builds against it (with the sanitizers' flags when the libraries carry them).
if(SPRINGCHECK_PYTHON)
  set(_consumer_flags "")
  if(SPRINGCHECK_SANITIZE)
    set(_consumer_flags "-fsanitize=address,undefined")
  endif()
  add_test(NAME install_runs_from_any_folder_and_builds_a_consumer
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/install_test.sh ${PROJECT_BINARY_DIR} "${_consumer_flags}")
  set_tests_properties(install_runs_from_any_folder_and_builds_a_consumer PROPERTIES
                       LABELS "install;cli;tooling" TIMEOUT 600)
endif()

# The docs name report pages by title, never by a number that moves.
add_test(NAME docs_cite_no_report_page_numbers
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/docs_numbers_test.sh ${PROJECT_SOURCE_DIR})
set_tests_properties(docs_cite_no_report_page_numbers PROPERTIES LABELS unit)

# run --obj-frames: every sampled frame as a numbered OBJ.
add_test(NAME obj_frames_write_every_frame_as_a_numbered_mesh
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/obj_frames_test.sh $<TARGET_FILE:springcheck> ${PROJECT_SOURCE_DIR})
set_tests_properties(obj_frames_write_every_frame_as_a_numbered_mesh PROPERTIES LABELS cli)

# engine init: the skeleton passes its own suite and gate from any folder (it needs {python}).
if(SPRINGCHECK_PYTHON)
  add_test(NAME engine_init_skeleton_passes_its_gate_from_any_folder
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/engine_init_test.sh $<TARGET_FILE:springcheck>)
  set_tests_properties(engine_init_skeleton_passes_its_gate_from_any_folder PROPERTIES
                       LABELS "external;cli;tooling" TIMEOUT 600)
endif()

# Label "tooling": a test whose time goes to Python, matplotlib, Slurm or a nested CMake build
# rather than to our C++; scripts/run-tests.sh runs these in the Release pass only (under the
# sanitizers they took 1 to 3 minutes each and checked no more of our code).

# The Debian package: built, its files and dependencies checked, unpacked and used with no source
# tree. Release builds only: a package of sanitizer-instrumented binaries is no one's package (the
# code it holds is tested under the sanitizers by every other test).
find_program(DPKG_DEB dpkg-deb)
if(SPRINGCHECK_PYTHON AND DPKG_DEB AND NOT SPRINGCHECK_SANITIZE)
  add_test(NAME debian_package_installs_and_runs_with_no_source_tree
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/package_test.sh ${PROJECT_BINARY_DIR})
  set_tests_properties(debian_package_installs_and_runs_with_no_source_tree PROPERTIES
                       LABELS "install;cli" TIMEOUT 600)
endif()

# Sweeps on a real Slurm: a single-node cluster on this machine runs the documented job array
# (examples/slurm/) and its merged table must equal a local run (skipped without root).
add_test(NAME slurm_job_array_matches_a_local_sweep
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/slurm_test.sh $<TARGET_FILE:springcheck> ${PROJECT_SOURCE_DIR})
set_tests_properties(slurm_job_array_matches_a_local_sweep PROPERTIES LABELS "slurm;cli;tooling" TIMEOUT 900
                     SKIP_RETURN_CODE 77 RESOURCE_LOCK slurm)

# The report: drawn from small tables the real commands make, every figure present and non-empty.
if(SPRINGCHECK_PYTHON)
  add_test(NAME report_builds_every_figure
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/report_test.sh $<TARGET_FILE:springcheck>
                   ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/report_test)
  set_tests_properties(report_builds_every_figure PROPERTIES LABELS "report;cli;tooling" TIMEOUT 600)
  # The main job whole, its budget held by counts (runs, steps per stage; scripts/main-job-work.json).
  # Release only (slow): about 6 minutes of both cores; started first (COST) so the other tests
  # fill the cores around it.
  add_test(NAME main_job_stays_within_its_recorded_work
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/main_job_work_test.sh ${PROJECT_SOURCE_DIR}
                   ${CMAKE_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR}/main_job)
  set_tests_properties(main_job_stays_within_its_recorded_work PROPERTIES
                       LABELS "report;cli;gate;slow;tooling" TIMEOUT 1800 COST 10000)
endif()

# refine given one resolution twice: refused, saying it needs distinct ones.
add_test(NAME refine_refuses_a_resolution_given_twice
         COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;refine;${PROJECT_SOURCE_DIR}/scenes/material/cantilever_strip.json;--resolutions;4,4;--out;${CMAKE_CURRENT_BINARY_DIR}/refine_twice"
                 -DCODE=2 "-DEXPECT=--resolutions: 4 given twice; expected distinct resolutions"
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
set_tests_properties(refine_refuses_a_resolution_given_twice PROPERTIES LABELS cli)
# refine: the cantilever converges at second order to the elastica; flex springs do not.
add_test(NAME refine_cantilever_converges_to_the_elastica_and_flex_springs_do_not
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/refine_test.sh $<TARGET_FILE:springcheck> ${PROJECT_SOURCE_DIR})
set_tests_properties(refine_cantilever_converges_to_the_elastica_and_flex_springs_do_not PROPERTIES
                     LABELS "cli;physics")

# springcheck trade's bad input: exit 2, naming the flag or field and what was expected.
foreach(case IN ITEMS
    "quantity_the_scene_lacks|material/cantilever_strip.json|--quantity;drape_coefficient;--max-error;0.01|--quantity: drape_coefficient is not a settled quantity"
    "scene_without_a_material|matched/chain_hanging.json|--quantity;sag_lowest;--max-error;0.01|system.material: expected a material scene"
    "bound_not_positive|material/cantilever_strip.json|--quantity;tip_drop;--max-error;0|--max-error: expected a finite number > 0"
    "steps_that_do_not_line_up|material/cantilever_strip.json|--quantity;tip_drop;--max-error;0.01;--dts;0.016,0.006|--dts: 0.006"
    "integrator_unknown|material/cantilever_strip.json|--quantity;tip_drop;--max-error;0.01;--integrators;xpbd:passes=3|--integrators:")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 scene)
  list(SUBLIST parts 2 -1 rest)
  list(POP_BACK rest expect)
  add_test(NAME trade_refuses_${name}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:springcheck>;trade;${PROJECT_SOURCE_DIR}/scenes/${scene};${rest};--out;${CMAKE_CURRENT_BINARY_DIR}/trade_refused_${name}"
                   -DCODE=2 "-DEXPECT=${expect}" -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake)
  set_tests_properties(trade_refuses_${name} PROPERTIES LABELS "validation;cli")
endforeach()

# The code's shape: no file over 400 lines, no C++ function over 60, but the recorded debt
# (scripts/code-shape-debt.txt), which may only shrink.
find_package(Python3 COMPONENTS Interpreter)
if(Python3_Interpreter_FOUND)
  add_test(NAME code_shape_holds_its_limits_but_the_recorded_debt
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check-code-shape.py
                   --debt ${PROJECT_SOURCE_DIR}/scripts/code-shape-debt.txt ${PROJECT_SOURCE_DIR})
  set_tests_properties(code_shape_holds_its_limits_but_the_recorded_debt PROPERTIES LABELS unit)
  add_test(NAME mysim_includes_keep_its_layer_order
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/check-mysim-layers.py
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(mysim_includes_keep_its_layer_order PROPERTIES LABELS unit)
  # docs/findings.md's numbers are held to the main job's tables by main_job_stays_within_its_
  # recorded_work; this shows the check can fail.
  add_test(NAME findings_check_refuses_a_number_its_table_contradicts
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/findings_check_test.sh ${Python3_EXECUTABLE}
                   ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/findings_check)
  set_tests_properties(findings_check_refuses_a_number_its_table_contradicts PROPERTIES LABELS unit)
  # The scale study's driver (scripts/run-scale.sh) on tiny cloths, so the heavy study does not
  # rot between its runs.
  foreach(study scale equal_error)
    add_test(NAME ${study}_study_writes_a_row_per_engine_and_size
             COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/scale_study_test.py
                     $<TARGET_FILE:springcheck> ${PROJECT_SOURCE_DIR}
                     ${CMAKE_CURRENT_BINARY_DIR}/${study}_study bench/${study}_study.json)
    set_tests_properties(${study}_study_writes_a_row_per_engine_and_size PROPERTIES LABELS tooling)
  endforeach()
endif()
