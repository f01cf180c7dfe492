# aogen::gl — the headless OpenGL runner (include/aogen/gl/): a variant's emitted GLSL run on
# OpenGL 4.5 through EGL's surfaceless platform (Mesa llvmpipe), when libglvnd's EGL and
# OpenGL libraries are found (libegl-dev, libgl-dev; the driver: libegl-mesa0, libgl1-mesa-dri).
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
set(AOGEN_HAVE_GL OFF)
if(TARGET OpenGL::OpenGL AND TARGET OpenGL::EGL)
  set(AOGEN_HAVE_GL ON)
  add_library(aogen_gl INTERFACE)
  add_library(aogen::gl ALIAS aogen_gl)
  target_link_libraries(aogen_gl INTERFACE aogen_core OpenGL::OpenGL OpenGL::EGL)
else()
  message(STATUS "aogen: EGL or OpenGL (libegl-dev, libgl-dev) not found; aogen::gl is not built")
endif()
