# Run after a test program is built (cmake -P, from glideshadows_test in tests/CMakeLists.txt):
# lists the program's GoogleTest tests and writes CTEST_FILE, which registers them with ctest in
# groups: the tests of one suite, at most GROUP_SIZE to a process, in the order the program
# lists them. A test whose name matches ALONE (a regular expression) gets a process of its own.
#
# Why groups: a test program's start is much of a small test's cost, and a group pays it once.
# A process that opens a window loads the Mesa stack with LLVM (about 50 ms of CPU in the
# Release build, measured on numeric_tests at 620c658, and more under the sanitizers); one that
# links OpenImageIO (image_file_tests, the image suites) relocates its ~260 libraries too, about 0.4 s.
# Most tests take a few milliseconds.
# ctest names a group LABEL.Suite (LABEL.Suite.2of4 when a suite needs several), a lone test
# LABEL.Suite.Test; the program's output names each test that fails.
#
# Inputs (-D): PROGRAM, LABEL, CTEST_FILE, WORKING_DIRECTORY, GROUP_SIZE, ALONE, ENVIRONMENT
# (one NAME=value) and ENVIRONMENT_MODIFICATION (one NAME=op:value).

execute_process(COMMAND "${PROGRAM}" --gtest_list_tests
  WORKING_DIRECTORY "${WORKING_DIRECTORY}"
  TIMEOUT 60
  OUTPUT_VARIABLE listing
  ERROR_VARIABLE listing_errors
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --gtest_list_tests failed (${status}): ${listing}${listing_errors}")
endif()

# The listing: a line "Suite." (a parameterised suite: "Prefix/Suite.", a typed one may add
# "  # TypeParam = ..."), then a line "  Test" for each of its tests (a parameterised test may
# add "  # GetParam() = ...").
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.( .*)?$")
    set(suite "${CMAKE_MATCH_1}")
    string(MAKE_C_IDENTIFIER "${suite}" key)
    list(APPEND suites "${suite}")
    set(tests_${key} "")
  elseif(line MATCHES "^  ([^ ]+)" AND DEFINED suite)
    list(APPEND tests_${key} "${suite}.${CMAKE_MATCH_1}")
  endif()
endforeach()

set(script "")
macro(register name filter)
  string(APPEND script
    "add_test([==[${name}]==] [==[${PROGRAM}]==] [==[--gtest_filter=${filter}]==])\n"
    "set_tests_properties([==[${name}]==] PROPERTIES LABELS ${LABEL}"
    " WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==] ENVIRONMENT [==[${ENVIRONMENT}]==]"
    " ENVIRONMENT_MODIFICATION [==[${ENVIRONMENT_MODIFICATION}]==])\n")
endmacro()

foreach(suite IN LISTS suites)
  string(MAKE_C_IDENTIFIER "${suite}" key)
  set(grouped "")
  foreach(test IN LISTS tests_${key})
    if(test MATCHES "${ALONE}")
      register("${LABEL}.${test}" "${test}")
    else()
      list(APPEND grouped "${test}")
    endif()
  endforeach()
  list(LENGTH grouped count)
  if(count EQUAL 0)
    continue()
  endif()
  math(EXPR groups "(${count} + ${GROUP_SIZE} - 1) / ${GROUP_SIZE}")
  math(EXPR last "${groups} - 1")
  foreach(group RANGE ${last})
    # Spread evenly: group g takes the tests whose index i has i * groups / count == g.
    set(filter "")
    set(index 0)
    foreach(test IN LISTS grouped)
      math(EXPR owner "${index} * ${groups} / ${count}")
      if(owner EQUAL group)
        list(APPEND filter "${test}")
      endif()
      math(EXPR index "${index} + 1")
    endforeach()
    string(REPLACE ";" ":" filter "${filter}")
    if(groups EQUAL 1)
      register("${LABEL}.${suite}" "${filter}")
    else()
      math(EXPR number "${group} + 1")
      register("${LABEL}.${suite}.${number}of${groups}" "${filter}")
    endif()
  endforeach()
endforeach()

file(WRITE "${CTEST_FILE}" "${script}")
