include(GoogleTest)

# fl_add_gtest(NAME name SOURCES a.cpp ... LIBS lib ... LABELS fast|physics|slow|... [TIMEOUT s])
# Registers one GoogleTest executable with ctest; every test in it carries the given labels.
# Labels live here, not in shell scripts: `ctest -L fast` is the fast set, `-L slow` the slow one.
function(fl_add_gtest)
  cmake_parse_arguments(ARG "" "NAME;TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main fl_flags)
  target_compile_definitions(${ARG_NAME} PRIVATE
    FRICTIONLAB_TEST_ASSET_DIR="${FRICTIONLAB_ASSET_DIR}"
    FRICTIONLAB_TEST_SOURCE_DIR="${FRICTIONLAB_SOURCE_DIR}"
    FRICTIONLAB_TEST_BINARY_DIR="${CMAKE_BINARY_DIR}")
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  gtest_discover_tests(${ARG_NAME} DISCOVERY_TIMEOUT 60)
  # gtest_discover_tests passes PROPERTIES through a list that splits "fast;physics" into separate
  # words (only the first label would survive, and the timeout would be lost): set the labels and
  # the timeout on the discovered tests from an include file ctest reads after discovery.
  set(properties ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_properties.cmake)
  file(WRITE ${properties}
       "if(DEFINED ${ARG_NAME}_TESTS)\n"
       "  set_tests_properties(\${${ARG_NAME}_TESTS} PROPERTIES LABELS \"${ARG_LABELS}\" TIMEOUT ${ARG_TIMEOUT})\n"
       "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${properties})
endfunction()

# fl_add_script_test(NAME name COMMAND ... LABELS ...): a test that runs a command.
function(fl_add_script_test)
  cmake_parse_arguments(ARG "" "NAME;TIMEOUT;WORKING_DIRECTORY" "COMMAND;LABELS" ${ARGN})
  if(NOT ARG_WORKING_DIRECTORY)
    set(ARG_WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
  endif()
  add_test(NAME ${ARG_NAME} COMMAND ${ARG_COMMAND} WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  set_tests_properties(${ARG_NAME} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT})
endfunction()
