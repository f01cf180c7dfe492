# aogen::vulkan — the headless Vulkan harness (include/aogen/vulkan/), when the Vulkan
# loader is found and aogen::compiler is built.
find_package(Vulkan QUIET)
set(AOGEN_HAVE_VULKAN OFF)
if(Vulkan_FOUND AND AOGEN_HAVE_COMPILER)
  set(AOGEN_HAVE_VULKAN ON)
  add_library(aogen_vulkan INTERFACE)
  add_library(aogen::vulkan ALIAS aogen_vulkan)
  set_target_properties(aogen_vulkan PROPERTIES EXPORT_NAME vulkan)  # installed as aogen::vulkan
  target_link_libraries(aogen_vulkan INTERFACE aogen_compiler Vulkan::Vulkan)
else()
  message(STATUS "aogen: Vulkan loader (libvulkan-dev) or aogen::compiler not found; aogen::vulkan is not built")
endif()
