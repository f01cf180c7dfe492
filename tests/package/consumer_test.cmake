# Configures, builds and runs examples/<EXAMPLE> against the aogen installed in PREFIX;
# the example's executable is <PROGRAM>.
#   cmake -DSOURCE=<aogen source> -DEXAMPLE=consumer -DPROGRAM=consumer -DPREFIX=<install prefix>
#         -DWORK=<scratch dir> -P consumer_test.cmake
file(REMOVE_RECURSE "${WORK}")
foreach(step
    "configure;${CMAKE_COMMAND};-S;${SOURCE}/examples/${EXAMPLE};-B;${WORK};-DCMAKE_PREFIX_PATH=${PREFIX}"
    "build;${CMAKE_COMMAND};--build;${WORK}"
    "run;${WORK}/${PROGRAM}")
  list(POP_FRONT step name)
  execute_process(COMMAND ${step} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${EXAMPLE} ${name} failed (${result}):\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "${EXAMPLE} output:\n${out}")
