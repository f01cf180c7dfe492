# Finds what aogen::compiler needs: glslang, SPIRV-Tools' optimizer and SPIRV-Cross.
# Used by aogen's own build and by the installed package config, so both agree.
# Sets aogen_compiler_dependencies_found and aogen_compiler_libraries.
# Call find_package(Threads) first: glslang's config needs it on Debian 12.
find_package(glslang CONFIG QUIET)
find_package(SPIRV-Tools-opt CONFIG QUIET)
foreach(part core glsl hlsl msl)
  find_package(spirv_cross_${part} CONFIG QUIET)
endforeach()

set(aogen_compiler_dependencies_found FALSE)
if(TARGET glslang::glslang AND TARGET SPIRV-Tools-opt AND TARGET spirv-cross-core
   AND TARGET spirv-cross-glsl AND TARGET spirv-cross-hlsl AND TARGET spirv-cross-msl)
  set(aogen_compiler_dependencies_found TRUE)
  set(aogen_compiler_libraries
    glslang::glslang glslang::SPIRV glslang::glslang-default-resource-limits
    SPIRV-Tools-opt
    spirv-cross-msl spirv-cross-hlsl spirv-cross-glsl spirv-cross-core)
endif()
