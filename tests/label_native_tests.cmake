# Run by ctest (TEST_INCLUDE_FILES, after gtest_discover_tests' own include file has added the
# tests of confvis_tests): gives the label vulkan_or_window to every test whose source file loads
# a Vulkan driver or opens an X11 window, as the pattern below finds it in that file or in a
# header it includes. The sanitizer stage (tools/sanitize.sh) runs those tests without
# LeakSanitizer: lavapipe, the Vulkan loader and libX11 keep or leak memory in modules the loader
# unloads before exit, whose frames no suppression can name. A new test in such a file, or a new
# file that uses them, is labelled without anyone listing it.
# Inputs (tests/CMakeLists.txt sets them in the include file it generates):
#   CONFVIS_TEST_BINARY     confvis_tests; its JSON test list names each test's source file
#   CONFVIS_TEST_BUILD_DIR  where the sources were compiled from (for relative __FILE__ paths)
#   confvis_tests_TESTS     the ctest names of the discovered tests (gtest_discover_tests)
cmake_policy(VERSION 3.25)  # IN_LIST; ctest reads this file with no policies set (include: scoped)
if(NOT EXISTS "${CONFVIS_TEST_BINARY}" OR NOT DEFINED confvis_tests_TESTS)
  return()
endif()
set(list_json "${CONFVIS_TEST_BINARY}_list.json")
execute_process(COMMAND "${CONFVIS_TEST_BINARY}" --gtest_list_tests "--gtest_output=json:${list_json}"
  OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE listed TIMEOUT 60)
if(NOT listed EQUAL 0 OR NOT EXISTS "${list_json}")
  message(WARNING "confvis_tests --gtest_list_tests failed (${listed}): no vulkan_or_window labels")
  return()
endif()
# What loading a Vulkan driver or opening a window looks like in a test source: the Vulkan test
# device and backend helpers, the Vulkan API, the windowed `view` helpers and windows, and the
# CLI run with the Vulkan backend.
set(native_pattern "vulkan_test_support\\.hpp|view_test_support\\.hpp|vulkan/vulkan\\.h|makeVulkanBackend|display_window\\.hpp|X11/|GLFW/|--backend vulkan|\"vulkan\"")

# uses_native(FILE OUT): whether FILE, or a header it includes with quotes (found beside it, as
# the compiler finds it), matches the pattern; each file read once (native_seen, native_files).
function(uses_native file out)
  if(file IN_LIST native_files)
    set(${out} TRUE PARENT_SCOPE)
    return()
  elseif(file IN_LIST native_seen OR NOT EXISTS "${file}")
    set(${out} FALSE PARENT_SCOPE)
    return()
  endif()
  set(native_seen ${native_seen} "${file}" PARENT_SCOPE)
  set(native_seen ${native_seen} "${file}")
  file(READ "${file}" source)
  set(found FALSE)
  if(source MATCHES "${native_pattern}")
    set(found TRUE)
  else()
    get_filename_component(dir "${file}" DIRECTORY)
    string(REGEX MATCHALL "#include \"[^\"]+\"" includes "${source}")
    foreach(include IN LISTS includes)
      string(REGEX REPLACE "#include \"([^\"]+)\"" "\\1" header "${include}")
      get_filename_component(header "${header}" ABSOLUTE BASE_DIR "${dir}")
      uses_native("${header}" found)
      if(found)
        break()
      endif()
    endforeach()
  endif()
  if(found)
    set(native_files ${native_files} "${file}" PARENT_SCOPE)
  endif()
  set(native_seen ${native_seen} PARENT_SCOPE)
  set(${out} ${found} PARENT_SCOPE)
endfunction()

file(READ "${list_json}" listing)
string(JSON suite_count LENGTH "${listing}" testsuites)
set(native_suites "")
set(native_seen "")
set(native_files "")
math(EXPR last_suite "${suite_count} - 1")
foreach(s RANGE ${last_suite})
  string(JSON suite GET "${listing}" testsuites ${s})
  string(JSON suite_name GET "${suite}" name)
  # The first test's file stands for its suite (gtest requires a suite's tests in one file).
  string(JSON file GET "${suite}" testsuite 0 file)
  get_filename_component(file "${file}" ABSOLUTE BASE_DIR "${CONFVIS_TEST_BUILD_DIR}")
  uses_native("${file}" native)
  if(native)
    # ctest names: SUITE.TEST, DISABLED_ dropped, typed suites without their /N (GoogleTest.cmake).
    string(REGEX REPLACE "^DISABLED_" "" suite_name "${suite_name}")
    string(REGEX REPLACE "/[0-9]+$" "" suite_name "${suite_name}")
    list(APPEND native_suites "${suite_name}")
  endif()
endforeach()

foreach(test IN LISTS confvis_tests_TESTS)
  string(REGEX REPLACE "\\..*" "" suite_name "${test}")
  if(suite_name IN_LIST native_suites)
    set_tests_properties("${test}" PROPERTIES LABELS vulkan_or_window)
  endif()
endforeach()
