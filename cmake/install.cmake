# Installing springcheck (docs/install.md). An install holds:
#   bin/springcheck
#   share/springcheck/{reports,scenes,examples,compare/tolerances.json,compare/sweeps}
#   share/man/man1/springcheck.1.gz, share/bash-completion/completions/springcheck
#   lib/libspringcheck_*.a, include/{mysim,reference,compare}/
#   lib/cmake/springcheck/springcheckConfig.cmake (+ version and targets files)
# The executable finds its data at ../share/springcheck from its own folder (cli/src/
# data_dir.h); the build tree gets the same layout, as links into the source tree, so the built
# binary behaves exactly like the installed one.
include(CMakePackageConfigHelpers)

set(SPRINGCHECK_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/springcheck)
set(SPRINGCHECK_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/springcheck)
# What springcheck carries as data, as paths in the source tree (kept as they are in the
# install, so the relative scene paths inside tolerances and sweep files still resolve).
set(SPRINGCHECK_DATA_DIRS scenes reports examples compare/sweeps)
set(SPRINGCHECK_DATA_FILES compare/tolerances.json)

# The build tree's share/springcheck, beside build/<preset>/cli/springcheck.
set(_build_data ${PROJECT_BINARY_DIR}/share/springcheck)
file(MAKE_DIRECTORY ${_build_data}/compare)
foreach(_item IN LISTS SPRINGCHECK_DATA_DIRS SPRINGCHECK_DATA_FILES)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${_item} ${_build_data}/${_item} SYMBOLIC)
endforeach()

# The executable and its data.
install(TARGETS springcheck RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(_dir IN LISTS SPRINGCHECK_DATA_DIRS)
  get_filename_component(_parent ${_dir} DIRECTORY)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_dir} DESTINATION ${SPRINGCHECK_INSTALL_DATADIR}/${_parent}
          PATTERN __pycache__ EXCLUDE)
endforeach()
foreach(_file IN LISTS SPRINGCHECK_DATA_FILES)
  get_filename_component(_parent ${_file} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${_file} DESTINATION ${SPRINGCHECK_INSTALL_DATADIR}/${_parent})
endforeach()
if(TARGET springcheck_man)
  install(FILES ${PROJECT_BINARY_DIR}/cli/springcheck.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()
install(FILES ${PROJECT_BINARY_DIR}/cli/springcheck.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME springcheck)

# The libraries, their headers and the package config.
install(TARGETS mysim reference springcheck_compare springcheck_compare_metrics springcheck_compare_io
                springcheck_compare_engines springcheck_compare_studies EXPORT springcheckTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(_include mysim reference compare/metrics compare/io compare/engines compare/studies)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_include}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
install(EXPORT springcheckTargets NAMESPACE springcheck:: DESTINATION ${SPRINGCHECK_INSTALL_CMAKEDIR})
configure_package_config_file(cmake/springcheckConfig.cmake.in
  ${PROJECT_BINARY_DIR}/install-config/springcheckConfig.cmake
  INSTALL_DESTINATION ${SPRINGCHECK_INSTALL_CMAKEDIR}
  PATH_VARS SPRINGCHECK_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/springcheckConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/install-config/springcheckConfig.cmake
              ${PROJECT_BINARY_DIR}/springcheckConfigVersion.cmake
        DESTINATION ${SPRINGCHECK_INSTALL_CMAKEDIR})

# The same package straight from this build tree (find_package with
# -Dspringcheck_DIR=build/release), without installing.
export(EXPORT springcheckTargets NAMESPACE springcheck:: FILE ${PROJECT_BINARY_DIR}/springcheckTargets.cmake)
set(SPRINGCHECK_INSTALL_DATADIR share/springcheck)
configure_package_config_file(cmake/springcheckConfig.cmake.in
  ${PROJECT_BINARY_DIR}/springcheckConfig.cmake
  INSTALL_DESTINATION . INSTALL_PREFIX ${PROJECT_BINARY_DIR}
  PATH_VARS SPRINGCHECK_INSTALL_DATADIR)
