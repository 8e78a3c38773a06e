# ctest labels from the test sources themselves (README lists the labels): every test file says
# what its suites are on a line
#     // ctest-label: LABEL[,LABEL...]
# and may label single suites otherwise on lines
#     // ctest-label SUITE: LABEL[,LABEL...]
# A test file without a label line stops the configure, naming the file: a new suite is never
# labelled by default. discover_labelled_tests(TARGET) registers the target's tests (through
# gtest_discover_tests) once per label set, each with the filter of its suites (parameterised
# suites as both SUITE.* and */SUITE.*).
function(discover_labelled_tests target)
  get_target_property(_sources ${target} SOURCES)
  set(_label_sets "")
  foreach(_source IN LISTS _sources)
    get_filename_component(_path ${_source} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    file(READ ${_path} _text)
    # The labels and suites are read here, at configure time: an edited test file configures
    # again, so a new or renamed suite is registered (without it, an incremental build left it out).
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_path})
    if(NOT _text MATCHES "// ctest-label: ([a-z,]+)")
      message(FATAL_ERROR "${_path}: no '// ctest-label: LABEL' line (tests/label_tests.cmake)")
    endif()
    set(_default ${CMAKE_MATCH_1})
    # A label list written with spaces kept only its first label (five files lost bullet,
    # external or physics that way until 2026-12-07): refused.
    if(_text MATCHES "// ctest-label[ A-Za-z0-9_]*: [a-z,]+[ \t]+[a-z]")
      message(FATAL_ERROR "${_path}: ctest labels are separated by commas, not spaces")
    endif()
    string(REGEX MATCHALL "(TEST|TEST_F|TEST_P)\\([A-Za-z0-9_]+," _uses "${_text}")
    set(_suites "")
    foreach(_use IN LISTS _uses)
      string(REGEX REPLACE ".*\\(([A-Za-z0-9_]+),$" "\\1" _suite "${_use}")
      list(APPEND _suites ${_suite})
    endforeach()
    list(REMOVE_DUPLICATES _suites)
    foreach(_suite IN LISTS _suites)
      set(_label ${_default})
      if(_text MATCHES "// ctest-label ${_suite}: ([a-z,]+)")
        set(_label ${CMAKE_MATCH_1})
      endif()
      string(REPLACE "," "_" _key "${_label}")
      if(DEFINED _suite_${_suite})
        # A suite spread over files (one executable) must carry one label set.
        if(NOT _suite_label_${_suite} STREQUAL _label)
          message(FATAL_ERROR "${_path}: suite ${_suite} is labelled ${_label} here and "
                              "${_suite_label_${_suite}} in ${_suite_${_suite}}")
        endif()
        continue()
      endif()
      set(_suite_${_suite} ${_path})
      set(_suite_label_${_suite} ${_label})
      list(APPEND _filter_${_key} "${_suite}.*" "*/${_suite}.*")
      list(APPEND _label_sets ${_label})
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES _label_sets)
  foreach(_label IN LISTS _label_sets)
    string(REPLACE "," "_" _key "${_label}")
    string(REPLACE ";" ":" _filter "${_filter_${_key}}")
    # The labels are set by a script of ours that ctest reads after the discovered tests, not by
    # gtest_discover_tests(PROPERTIES LABELS ...): that flattens a list into name/value pairs, so
    # every test kept only its first label ("physics,bullet,slow" was "physics", and the
    # sanitizer pass's --label-exclude slow excluded nothing).
    set(_list ${target}_${_key}_TESTS)
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${_filter}" TEST_LIST ${_list})
    string(REPLACE "," ";" _labels "${_label}")
    # The quick tier (README): every gtest suite that needs no Bullet, no other program, no
    # whole-run study: what a developer runs on every change (ctest -L quick, under a minute).
    set(_quick TRUE)
    foreach(_heavy IN ITEMS bullet external slow tooling cli report viewer gate slurm)
      if(_heavy IN_LIST _labels)
        set(_quick FALSE)
      endif()
    endforeach()
    if(_quick)
      list(APPEND _labels quick)
    endif()
    set(_script ${CMAKE_CURRENT_BINARY_DIR}/${target}_${_key}_labels.cmake)
    file(WRITE ${_script}
         "if(${_list})\n  set_tests_properties(\${${_list}} PROPERTIES LABELS \"${_labels}\")\nendif()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${_script})
  endforeach()
endfunction()
