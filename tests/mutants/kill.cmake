# Runs a test with a mutant planted and passes only when the mutant is killed: the test ran,
# the mutant was planted (template and emitted mutants say so on stderr; a source mutant is
# in the executable itself), and the test failed on an assertion — not only on a thrown
# exception (a mutant whose anchor no longer matches throws, one whose shader does not
# compile is stillborn), not by crashing, not by passing.
#   cmake -DMUTANT=<name> -DKIND=<kind> -DEXE=<test executable> -DTESTS=<Catch test spec> -P kill.cmake
foreach(var MUTANT KIND EXE TESTS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "kill.cmake: ${var} is not set")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E env AOGEN_MUTANT=${MUTANT} AOGEN_TESTS_OPTIONAL_DEPS=0 ${EXE} ${TESTS}
                OUTPUT_VARIABLE out ERROR_VARIABLE out RESULT_VARIABLE rc)
string(LENGTH "${out}" length)
if(length GREATER 6000)
  math(EXPR from "${length} - 6000")
  string(SUBSTRING "${out}" ${from} 6000 tail)
else()
  set(tail "${out}")
endif()
if(NOT KIND STREQUAL "source" AND NOT out MATCHES "aogen mutant ${MUTANT}: planted in")
  message(FATAL_ERROR "mutant ${MUTANT}: never planted (no test read its file)\n${tail}")
endif()
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "mutant ${MUTANT}: the test crashed (${rc}), which is not a kill\n${tail}")
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "mutant ${MUTANT} SURVIVED: ${TESTS} passed with it planted\n${tail}")
endif()
# A mutant that does not compile (glslang refuses the edited template) is stillborn, not killed.
if(out MATCHES "compilation errors")
  message(FATAL_ERROR "mutant ${MUTANT}: stillborn, its shader does not compile\n${tail}")
endif()
if(out MATCHES "is not found exactly once")
  message(FATAL_ERROR "mutant ${MUTANT}: its text is no longer in its file (update mutants.json)\n${tail}")
endif()
# Killed: at least one assertion failed on its own. (A REQUIRE failing inside a CHECK's
# expression also reports the CHECK as an "unexpected exception": those are not counted.)
string(REGEX MATCHALL "FAILED:" failures "${out}")
string(REGEX MATCHALL "due to unexpected exception" exceptions "${out}")
list(LENGTH failures failure_count)
list(LENGTH exceptions exception_count)
if(NOT failure_count GREATER exception_count)
  message(FATAL_ERROR "mutant ${MUTANT}: exit ${rc} without a failed assertion (${failure_count} failures, ${exception_count} exceptions)\n${tail}")
endif()
message(STATUS "mutant ${MUTANT}: killed by ${TESTS}")
