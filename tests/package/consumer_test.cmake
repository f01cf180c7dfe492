# Configures, builds and runs examples/<EXAMPLE> against the aogen installed in PREFIX;
# the example's executable is <PROGRAM>, and <PROGRAM>_vulkan runs too where the example
# built one. When the installed package has aogen::vulkan, the example is configured with
# AOGEN_CONSUMER_REQUIRE_VULKAN=ON (examples that build a Vulkan program then require the
# component; the others ignore it).
#   cmake -DSOURCE=<aogen source> -DEXAMPLE=consumer -DPROGRAM=consumer -DPREFIX=<install prefix>
#         -DWORK=<scratch dir> -P consumer_test.cmake
file(REMOVE_RECURSE "${WORK}")
# A Vulkan example without a device fails here (install-deps installs lavapipe), unless
# AOGEN_TESTS_OPTIONAL_DEPS=1 says this machine cannot have one.
set(require_device AOGEN_REQUIRE_DEVICE=1)
if("$ENV{AOGEN_TESTS_OPTIONAL_DEPS}" STREQUAL "1")
  set(require_device AOGEN_TESTS_OPTIONAL_DEPS=1)
endif()
file(GLOB_RECURSE vulkan_targets "${PREFIX}/*/aogenVulkanTargets.cmake")
set(require_vulkan OFF)
if(vulkan_targets)
  set(require_vulkan ON)
endif()
foreach(step
    "configure;${CMAKE_COMMAND};-S;${SOURCE}/examples/${EXAMPLE};-B;${WORK};-DCMAKE_PREFIX_PATH=${PREFIX};-DAOGEN_CONSUMER_REQUIRE_VULKAN=${require_vulkan};--no-warn-unused-cli"
    "build;${CMAKE_COMMAND};--build;${WORK}"
    "run;${WORK}/${PROGRAM}"
    "run Vulkan;${CMAKE_COMMAND};-E;env;${require_device};${WORK}/${PROGRAM}_vulkan")
  list(POP_FRONT step name)
  if(name STREQUAL "run Vulkan" AND NOT EXISTS "${WORK}/${PROGRAM}_vulkan")
    continue()
  endif()
  execute_process(COMMAND ${step} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${EXAMPLE} ${name} failed (${result}):\n${out}\n${err}")
  endif()
  if(name MATCHES "^run")
    string(APPEND output "${out}")
  endif()
endforeach()
message(STATUS "${EXAMPLE} output:\n${output}")
