# tests/ts/build_module.cmake — the TypeScript module the ts tests read, made once at build time
# (tests/CMakeLists.txt runs it): `aogen generate --targets wgsl,ts` for the variants of a file
# (module_variants.txt), or without one for the default matrix, then the pinned tsc --strict
# over it (its tsconfig.json), into OUT/ts/dist.
#
#   cmake -DAOGEN=<aogen> -DNODE=<node> -DTOOLS=<source>/wgsl [-DVARIANTS=<file>] -DOUT=<dir> -P build_module.cmake
#
# It never fails the build: where a step fails (no Node.js, no npm packages, a tsc error) it
# writes OUT/FAILED naming the step and what it said, and every test that reads the module fails
# with that text (ts_support.hpp) while the rest of the suite runs. A test run under a mutant
# aimed at the module ("ts:aogen.ts") plants it in a copy of this text and compiles that.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(variants) # none: the default matrix
if(VARIANTS)
  file(STRINGS "${VARIANTS}" variants REGEX "^[a-z]")
endif()

# Runs the command after `what`; on failure writes OUT/FAILED and stops the script.
macro(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE said ERROR_VARIABLE said)
  if(NOT status EQUAL 0)
    file(WRITE "${OUT}/FAILED" "the ts tests' module: ${what} failed (${status}): ${said}")
    message(WARNING "the ts tests' module: ${what} failed; the ts tests will fail with ${OUT}/FAILED")
    return()
  endif()
endmacro()

if(NOT NODE OR NOT EXISTS "${NODE}")
  file(WRITE "${OUT}/FAILED" "the ts tests' module: needs Node.js, and CMake found no `node` (valid: scripts/install-deps.sh installs it)")
  return()
endif()
step("aogen generate --targets wgsl,ts" "${AOGEN}" generate --quiet --targets wgsl,ts --out "${OUT}" ${variants})
# The module's one dependency, @webgpu/types, where a project keeps it: its node_modules.
file(CREATE_LINK "${TOOLS}/node_modules" "${OUT}/ts/node_modules" SYMBOLIC)
step("tsc --strict" "${NODE}" "${TOOLS}/node_modules/typescript/bin/tsc" -p "${OUT}/ts")
file(WRITE "${OUT}/BUILT" "")
