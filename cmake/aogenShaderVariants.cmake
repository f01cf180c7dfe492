# aogen_add_shader_variants(<target>
#     [VARIANTS <name>...]          canonical variant names (see `aogen list`)
#     [SPEC <file.json>]            a variant spec (names and/or matrices)
#     [SCENE <file.json>]           what the renderer has and needs: selects features
#     [TARGETS <t>...]              spv glsl essl hlsl hlsl60 msl msl_ios wgsl (default: spv;
#                                   wgsl needs Node.js and the WGSL tools: docs/webgpu.md § WebGPU)
#     [OUTPUT_DIR <dir>])           default: ${CMAKE_CURRENT_BINARY_DIR}/aogen/<target>
#
# Generates the variants' shaders at build time with `aogen generate` and makes the
# generated header available to <target>: `#include <aogen_variants.hpp>`. The
# generator re-runs when the spec, the scene or the aogen tool changes (the templates
# are compiled into the tool). With neither VARIANTS nor SPEC, the default matrix.
function(aogen_add_shader_variants target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "SPEC;SCENE;OUTPUT_DIR" "VARIANTS;TARGETS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "aogen_add_shader_variants: unknown arguments ${arg_UNPARSED_ARGUMENTS} "
                        "(valid: VARIANTS, SPEC, SCENE, TARGETS, OUTPUT_DIR)")
  endif()
  if(TARGET aogen::aogen)
    set(tool aogen::aogen)
  elseif(TARGET aogen)
    set(tool aogen)
  else()
    message(FATAL_ERROR "aogen_add_shader_variants: no aogen tool target (find_package(aogen) or build aogen)")
  endif()
  if(NOT arg_OUTPUT_DIR)
    set(arg_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/aogen/${target})
  endif()
  if(NOT arg_TARGETS)
    set(arg_TARGETS spv)
  endif()
  list(JOIN arg_TARGETS "," targets)

  set(args generate --out ${arg_OUTPUT_DIR} --targets ${targets})
  set(depends ${tool} $<TARGET_FILE:${tool}>)
  foreach(input SPEC SCENE)
    if(arg_${input})
      get_filename_component(file ${arg_${input}} ABSOLUTE)
      string(TOLOWER ${input} option)
      if(option STREQUAL "spec")
        set(option variants)
      endif()
      list(APPEND args --${option} ${file})
      list(APPEND depends ${file})
    endif()
  endforeach()
  list(APPEND args ${arg_VARIANTS})

  add_custom_command(
    OUTPUT ${arg_OUTPUT_DIR}/aogen_variants.hpp ${arg_OUTPUT_DIR}/manifest.json
    COMMAND ${tool} ${args}
    DEPENDS ${depends}
    COMMENT "aogen: generating shader variants for ${target}"
    VERBATIM)
  add_custom_target(${target}_aogen_variants DEPENDS ${arg_OUTPUT_DIR}/aogen_variants.hpp)
  add_dependencies(${target} ${target}_aogen_variants)
  target_include_directories(${target} PRIVATE ${arg_OUTPUT_DIR})
endfunction()
