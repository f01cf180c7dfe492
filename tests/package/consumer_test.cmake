# Configures, builds and runs examples/consumer against the aogen installed in PREFIX.
#   cmake -DSOURCE=<aogen source> -DPREFIX=<install prefix> -DWORK=<scratch dir> -P consumer_test.cmake
file(REMOVE_RECURSE "${WORK}")
foreach(step
    "configure;${CMAKE_COMMAND};-S;${SOURCE}/examples/consumer;-B;${WORK};-DCMAKE_PREFIX_PATH=${PREFIX}"
    "build;${CMAKE_COMMAND};--build;${WORK}"
    "run;${WORK}/consumer")
  list(POP_FRONT step name)
  execute_process(COMMAND ${step} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "consumer ${name} failed (${result}):\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "consumer output:\n${out}")
