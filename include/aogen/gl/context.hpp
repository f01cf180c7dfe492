// aogen/gl/context.hpp — a headless OpenGL 4.5 core context through EGL's surfaceless
// platform (Mesa: llvmpipe), for running a variant's emitted GLSL (aogen/gl/chain.hpp).
//
// WHAT
//   context() opens EGL_PLATFORM_SURFACELESS_MESA's default display, binds the OpenGL API and
//   makes a 4.5 core context current on this thread with no surface: compute shaders, textures
//   and image load/store need none. version() and renderer() are GL's strings
//   ("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)").
//
// USAGE
//     aogen::gl::context gl;                        // throws aogen::error without EGL/GL 4.5
//     std::string v = gl.version();
//
// Link: OpenGL::EGL and OpenGL::OpenGL (libglvnd's libEGL and libOpenGL; CMake target aogen::gl).
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include "../error.hpp"

#include <string>

namespace aogen::gl {

class context {
public:
    context()
    {
        const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!platform_display) fail("EGL", "has no eglGetPlatformDisplayEXT", "valid: an EGL 1.5 implementation (libegl-mesa0)");
        display_ = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
            fail("EGL", "cannot open the surfaceless platform's display", "valid: Mesa's EGL (libegl-mesa0, libgl1-mesa-dri)");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("EGL", "cannot bind the OpenGL API", "valid: an EGL with desktop OpenGL");
        const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        eglChooseConfig(display_, config_attributes, &config, 1, &configs);
        const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,       4, EGL_CONTEXT_MINOR_VERSION, 5,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context_ = eglCreateContext(display_, configs > 0 ? config : EGLConfig(nullptr), EGL_NO_CONTEXT, context_attributes);
        if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            eglTerminate(display_);
            fail("EGL", "cannot make an OpenGL 4.5 core context current without a surface", "valid: Mesa 20 or later (llvmpipe)");
        }
    }
    context(const context&) = delete;
    context& operator=(const context&) = delete;
    ~context()
    {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    std::string version() const { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }
    std::string renderer() const { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace aogen::gl
