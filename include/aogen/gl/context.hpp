// aogen/gl/context.hpp — a headless OpenGL 4.5 core or OpenGL ES 3.2 context through EGL's
// surfaceless platform (Mesa: llvmpipe), for running a variant's emitted GLSL or ESSL
// (aogen/gl/chain.hpp).
//
// WHAT
//   context(api) opens EGL_PLATFORM_SURFACELESS_MESA's default display, binds the OpenGL or
//   OpenGL ES API and makes a 4.5 core / ES 3.2 context current on this thread with no
//   surface: compute shaders, textures and image load/store need none. version() and
//   renderer() are GL's strings ("4.5 (Core Profile) Mesa 22.3.6", "OpenGL ES 3.2 Mesa
//   22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)"). One context at a time per thread.
//
// USAGE
//     aogen::gl::context gl;                        // throws aogen::error without EGL/GL 4.5
//     aogen::gl::context es(aogen::gl::api::opengl_es);
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

#include <aogen/error.hpp>

#include <string>

namespace aogen::gl {

enum class api { opengl, opengl_es };

class context {
public:
    explicit context(gl::api which = gl::api::opengl) : api_(which)
    {
        const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!platform_display) fail("EGL", "has no eglGetPlatformDisplayEXT", "valid: an EGL 1.5 implementation (libegl-mesa0)");
        display_ = platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
            fail("EGL", "cannot open the surfaceless platform's display", "valid: Mesa's EGL (libegl-mesa0, libgl1-mesa-dri)");
        const bool es = which == gl::api::opengl_es;
        if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
            fail("EGL", std::string("cannot bind the ") + (es ? "OpenGL ES" : "OpenGL") + " API", "valid: Mesa's EGL with both");
        const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        eglChooseConfig(display_, config_attributes, &config, 1, &configs);
        const EGLint desktop_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,       4, EGL_CONTEXT_MINOR_VERSION, 5,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        const EGLint es_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
        context_ = eglCreateContext(display_, configs > 0 ? config : EGLConfig(nullptr), EGL_NO_CONTEXT, es ? es_attributes : desktop_attributes);
        if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            eglTerminate(display_);
            fail("EGL", std::string("cannot make an ") + (es ? "OpenGL ES 3.2" : "OpenGL 4.5 core") + " context current without a surface",
                 "valid: Mesa 20 or later (llvmpipe)");
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

    gl::api api() const { return api_; }
    // Makes this context the thread's current one again (another context may have been made
    // current since); aogen::gl::run calls it first.
    void make_current() const
    {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("EGL", "cannot make the context current again", "valid: a live context");
    }
    // GL's strings of this context (made current first: GL answers for the current one).
    std::string version() const { return text(GL_VERSION); }
    std::string renderer() const { return text(GL_RENDERER); }

private:
    std::string text(GLenum which) const
    {
        make_current();
        return reinterpret_cast<const char*>(glGetString(which));
    }

    gl::api api_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace aogen::gl
