// aogen/gl/chain.hpp — a variant's compute chain run from its emitted GLSL 450 on OpenGL 4.5,
// or its ESSL 310 on OpenGL ES 3.2 (aogen/gl/context.hpp), on the same bytes the Vulkan
// harness uploads (aogen/chain_inputs.hpp).
//
// WHAT
//   run(ctx, v, glsl, g, in, o) compiles each pass's text (SPIRV-Cross's GLSL 450 or ESSL 310
//   output of codegen::generate(v, o): one compute shader per pass of passes(v), in order;
//   ESSL needs o.output_format rgba8), uploads the
//   G-buffer (depth R32F, normals RGBA32F), the noise tile (RGBA32F) and each pass's std140
//   uniform block, binds every resource codegen::resources() lists at its binding (GL keeps
//   the numbers: uniform blocks, texture units and image units each have their own), runs
//   the passes with a memory barrier between them and reads the last output back as floats
//   k / 255. Outputs are R8 (or RGBA8) images: the AO target's size, the screen's for the upsample;
//   compute passes are dispatched over their output size / pixels_per_invocation.
//   Samplers: nearest, clamp-to-edge (depth, normals, AO input) and repeat (noise), as the
//   Vulkan harness's.
//
// USAGE
//     aogen::gl::context gl;
//     std::vector<std::string> glsl = ...;   // compile::compile(s.glsl, ..., {target::glsl}).text
//     aogen::gl::chain_result r = aogen::gl::run(gl, v, glsl, g, aogen::inputs_for(v, s, tw, th));
//
// ERRORS
//   aogen::error: a fragment variant (not run here yet), a text count other than the pass
//   count, a GLSL compile or link error (with GL's log), a G-buffer of the wrong size, a pass
//   reading normals the G-buffer does not have.
#pragma once

#include "../chain_inputs.hpp"
#include "../codegen.hpp"
#include "context.hpp"

#include <memory>
#include <string>
#include <vector>

namespace aogen::gl {

struct chain_result {
    int width = 0, height = 0;
    std::vector<float> ao; // width × height, the last pass's output, k / 255
};

namespace detail {

// The GL objects one run makes, deleted when it ends.
struct objects {
    std::vector<GLuint> textures, buffers, samplers, programs;
    objects() = default;
    objects(const objects&) = delete;
    objects& operator=(const objects&) = delete;
    ~objects()
    {
        glDeleteTextures(GLsizei(textures.size()), textures.data());
        glDeleteBuffers(GLsizei(buffers.size()), buffers.data());
        glDeleteSamplers(GLsizei(samplers.size()), samplers.data());
        for (GLuint p : programs) glDeleteProgram(p);
    }

    // The calls below are OpenGL 4.5's and OpenGL ES 3.1's both (no direct state access).
    GLuint texture(int w, int h, GLenum format, GLenum upload_format, GLenum type, const void* data)
    {
        GLuint t = 0;
        glGenTextures(1, &t);
        textures.push_back(t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (data) glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, upload_format, type, data);
        return t;
    }
    GLuint sampler(GLenum wrap)
    {
        GLuint s = 0;
        glGenSamplers(1, &s);
        samplers.push_back(s);
        glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GLint(wrap));
        glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GLint(wrap));
        return s;
    }
    GLuint uniform_buffer(const std::vector<uint8_t>& bytes)
    {
        GLuint b = 0;
        glGenBuffers(1, &b);
        buffers.push_back(b);
        glBindBuffer(GL_UNIFORM_BUFFER, b);
        glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(bytes.size()), bytes.data(), GL_STATIC_DRAW);
        return b;
    }
    GLuint program(const std::string& glsl, const std::string& name)
    {
        const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
        const char* text = glsl.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
            glDeleteShader(shader);
            fail("gl " + name, "does not compile: " + log, "valid: GLSL 450 or ESSL 310 as compile.hpp's glsl and essl targets write them");
        }
        const GLuint p = glCreateProgram();
        programs.push_back(p);
        glAttachShader(p, shader);
        glLinkProgram(p);
        glDeleteShader(shader);
        glGetProgramiv(p, GL_LINK_STATUS, &ok);
        if (!ok) fail("gl " + name, "does not link: " + info_log(p, glGetProgramiv, glGetProgramInfoLog), "valid: one compute shader");
        return p;
    }

private:
    template <class Get, class Log>
    static std::string info_log(GLuint object, Get get, Log log)
    {
        GLint length = 0;
        get(object, GL_INFO_LOG_LENGTH, &length);
        std::string text(size_t(length > 0 ? length : 1), '\0');
        log(object, GLsizei(text.size()), nullptr, text.data());
        return text.c_str();
    }
};

inline GLuint groups(int size, int per_invocation, int workgroup)
{
    const int invocations = (size + per_invocation - 1) / per_invocation;
    return GLuint((invocations + workgroup - 1) / workgroup);
}

// The AO of the last pass's output texture `t` (w × h, format R8 or RGBA8: .r), read through a
// framebuffer as RGBA bytes, which both OpenGL and OpenGL ES read from any unorm attachment.
inline std::vector<float> read_back(GLuint t, int w, int h)
{
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
    std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    std::vector<float> ao(size_t(w) * size_t(h));
    for (size_t p = 0; p < ao.size(); ++p) ao[p] = rgba[4 * p] / 255.0f;
    return ao;
}

inline GLenum image_format(const std::string& output_format)
{
    if (output_format == "r8") return GL_R8;
    if (output_format == "rgba8") return GL_RGBA8;
    fail("gl chain output format", quote(output_format) + " is not run here", "valid: r8, rgba8");
}

} // namespace detail

// `o` must be the codegen options the texts were generated with (their output format).
inline chain_result run(const context& ctx, const variant& v, const std::vector<std::string>& glsl, const gbuffer& g, const chain_inputs& in,
                        const codegen::options& o = {})
{
    ctx.make_current();
    validate(v);
    if (v.stage != pipeline_stage::compute)
        fail("gl chain", to_name(v) + " is a fragment variant", "valid: compute variants (fragment passes are not run on GL yet)");
    const std::vector<pass_kind> kinds = passes(v);
    if (glsl.size() != kinds.size() || in.uniforms.size() != kinds.size())
        fail("gl chain", std::to_string(glsl.size()) + " GLSL texts and " + std::to_string(in.uniforms.size()) + " uniform blocks for " + to_name(v),
             "valid: one of each per pass, " + std::to_string(kinds.size()));
    const size_t pixels = size_t(g.width) * size_t(g.height);
    if (g.width < 1 || g.height < 1 || g.depth.size() != pixels || (!g.normals.empty() && g.normals.size() != 4 * pixels))
        fail("gl chain", "G-buffer of " + std::to_string(g.width) + "x" + std::to_string(g.height) + " with " + std::to_string(g.depth.size()) + " depths",
             "valid: width × height depths and none or 4 × that normals");

    detail::objects gl;
    const GLuint depth = gl.texture(g.width, g.height, GL_R32F, GL_RED, GL_FLOAT, g.depth.data());
    const GLuint normals = g.normals.empty() ? 0 : gl.texture(g.width, g.height, GL_RGBA32F, GL_RGBA, GL_FLOAT, g.normals.data());
    const GLuint noise = gl.texture(in.noise_size, in.noise_size, GL_RGBA32F, GL_RGBA, GL_FLOAT, in.noise.data());
    const GLuint clamp = gl.sampler(GL_CLAMP_TO_EDGE), repeat = gl.sampler(GL_REPEAT);
    const auto [tw, th] = target_size(v, g.width, g.height);

    const GLenum format = detail::image_format(o.output_format);
    GLuint previous = 0;
    int out_w = 0, out_h = 0;
    for (size_t i = 0; i < kinds.size(); ++i) {
        const pass_kind pass = kinds[i];
        const std::string name = to_name(v) + "." + names::name_of(pass_kind_names, pass, "pass");
        out_w = pass == pass_kind::upsample ? g.width : tw, out_h = pass == pass_kind::upsample ? g.height : th;
        const GLuint output = gl.texture(out_w, out_h, format, GL_RED, GL_UNSIGNED_BYTE, nullptr);
        glUseProgram(gl.program(glsl[i], name));
        for (const codegen::resource& r : codegen::resources(v, pass, shader_stage::compute, o)) {
            const GLuint unit = r.binding;
            if (r.kind == codegen::resource_kind::uniform_buffer) {
                glBindBufferBase(GL_UNIFORM_BUFFER, unit, gl.uniform_buffer(in.uniforms[i]));
            } else if (r.kind == codegen::resource_kind::storage_image) {
                if (r.name != "output") fail("gl " + name, "binds storage image '" + r.name + "'", "valid: output (no diagnostics on GL)");
                glBindImageTexture(unit, output, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
            } else {
                GLuint texture = 0, sampler = clamp;
                if (r.name == "depth") texture = depth;
                else if (r.name == "normals") texture = normals;
                else if (r.name == "noise") texture = noise, sampler = repeat;
                else if (r.name == "ao_input") texture = previous;
                if (!texture) fail("gl " + name, "reads '" + r.name + "', which this run has not", "valid: depth, normals (a G-buffer with them), noise, ao_input");
                glActiveTexture(GL_TEXTURE0 + unit);
                glBindTexture(GL_TEXTURE_2D, texture);
                glBindSampler(unit, sampler);
            }
        }
        const int k = pixels_per_invocation(pass, pipeline_stage::compute);
        glDispatchCompute(detail::groups(out_w, k, v.workgroup_x), detail::groups(out_h, k, v.workgroup_y), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
        previous = output;
    }
    chain_result r;
    r.width = out_w, r.height = out_h;
    r.ao = detail::read_back(previous, out_w, out_h);
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) fail("gl chain " + to_name(v), "GL error " + std::to_string(error), "valid: none");
    return r;
}

} // namespace aogen::gl
