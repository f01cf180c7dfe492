// aogen/gl/chain.hpp — a variant's chain run from its emitted GLSL 450 on OpenGL 4.5, or its
// ESSL (310 compute, 300 fragment) on OpenGL ES 3.2 (aogen/gl/context.hpp), on the same bytes
// the Vulkan harness uploads (aogen/chain_inputs.hpp).
//
// WHAT
//   run(ctx, plan, texts, g, in) compiles each pass's texts (SPIRV-Cross's GLSL 450 or ESSL
//   of the plan, emitted_texts(plan, target): one text per shader of the plan, in its order,
//   per pass a compute shader, or a vertex and a fragment shader; ESSL compute needs the
//   rgba8 output format, which emitted_texts gives it), uploads the G-buffer (depth R32F, normals RGBA32F), the noise tile
//   (RGBA32F) and each pass's std140 uniform block (plan.inputs), binds every resource the
//   plan's shader lists at its binding, runs the passes in order and reads the last output back as floats
//   k / 255.
//   Bindings: GLSL 450 and ESSL 310 carry them in the text (uniform blocks, texture units and
//   image units each have their own numbers), and the runner binds there. ESSL 300 has no
//   binding qualifiers, so for those texts the runner does what an application must: it
//   gives each uniform block (by its block name) and each sampler (u_<resource name>, as the
//   templates declare them) the manifest's binding number.
//   Compute passes write R8 (or RGBA8) images, dispatched over their output size /
//   pixels_per_invocation, with a memory barrier between passes. Fragment passes draw the
//   fullscreen triangle (3 vertices, no buffers) into an R8 texture through a framebuffer
//   (the history pass into two: the R8 AO and, attachment 1, its RGBA16F history), the
//   viewport the output's size, dithering off. Output sizes: the AO target's, the
//   screen's for the upsample. GL's window origin is the lower left, Vulkan's the upper left,
//   but both write window row k to texture row k and read texel row k there, so
//   ivec2(gl_FragCoord.xy) names the same texel on both.
//   Samplers: nearest, clamp-to-edge (depth, normals, AO input) and repeat (noise), as the
//   Vulkan harness's.
//   run_frames(ctx, plan, texts, g, frames) runs frame after frame (each frame's inputs, one
//   G-buffer) on one set of programs and images, as a frame loop does: a history pass's two
//   rgba16f history images (cleared before the first frame) are swapped after each frame, and
//   every frame's output is read back. run() is its one frame.
//
// USAGE
//     aogen::gl::context gl;
//     const aogen::codegen::plan p = aogen::plan_for(aogen::codegen::make_plan(v), aogen::compile::target::essl);
//     std::vector<std::string> texts = aogen::emitted_texts(p, aogen::compile::target::essl); // aogen/emitted.hpp
//     aogen::gl::chain_result r = aogen::gl::run(gl, p, texts, g, p.inputs(s, g.width, g.height));
//
// ERRORS
//   aogen::error: a text count other than the shader count, a GLSL compile or link error (with
//   GL's log), a G-buffer of the wrong size, a pass reading normals the G-buffer does not have,
//   a diagnostics build (its raw image is not run here).
#pragma once

#include <aogen/bent_normals.hpp>
#include <aogen/chain_inputs.hpp>
#include <aogen/codegen.hpp>
#include <aogen/emitted.hpp>
#include "context.hpp"

#include <memory>
#include <string>
#include <vector>

namespace aogen::gl {

struct chain_result {
    int width = 0, height = 0;
    std::vector<float> ao; // width × height, the last pass's output, k / 255
    std::vector<float> bent_normal; // a -bn variant's: 3 per pixel, view space (aogen/bent_normals.hpp); else empty
};

namespace detail {

// The GL objects one run makes, deleted when it ends.
struct objects {
    std::vector<GLuint> textures, buffers, samplers, programs;
    GLuint framebuffer_ = 0, vertex_array_ = 0;
    objects() = default;
    objects(const objects&) = delete;
    objects& operator=(const objects&) = delete;
    ~objects()
    {
        glDeleteTextures(GLsizei(textures.size()), textures.data());
        glDeleteBuffers(GLsizei(buffers.size()), buffers.data());
        glDeleteSamplers(GLsizei(samplers.size()), samplers.data());
        for (GLuint p : programs) glDeleteProgram(p);
        if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
        if (vertex_array_) glDeleteVertexArrays(1, &vertex_array_);
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
    // The program of one pass from its shaders' texts: {compute} or {vertex, fragment}.
    GLuint program(const std::vector<std::pair<GLenum, const std::string*>>& shaders, const std::string& name)
    {
        const GLuint p = glCreateProgram();
        programs.push_back(p);
        for (const auto& [stage, glsl] : shaders) {
            const GLuint shader = glCreateShader(stage);
            const char* text = glsl->c_str();
            glShaderSource(shader, 1, &text, nullptr);
            glCompileShader(shader);
            GLint ok = 0;
            glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
            if (!ok) {
                const std::string log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
                glDeleteShader(shader);
                fail("gl " + name, "does not compile: " + log, "valid: GLSL 450 or ESSL 310/300 as compile.hpp's glsl and essl targets write them");
            }
            glAttachShader(p, shader);
            glDeleteShader(shader); // freed with the program
        }
        glLinkProgram(p);
        GLint ok = 0;
        glGetProgramiv(p, GL_LINK_STATUS, &ok);
        if (!ok) fail("gl " + name, "does not link: " + info_log(p, glGetProgramiv, glGetProgramInfoLog), "valid: one pass's shaders");
        return p;
    }
    GLuint framebuffer()
    {
        if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
        return framebuffer_;
    }
    GLuint vertex_array() // core profiles draw only with one bound, even without attributes
    {
        if (!vertex_array_) glGenVertexArrays(1, &vertex_array_);
        return vertex_array_;
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

// The last pass's output texture `t` (w × h, format R8 or RGBA8), read through a framebuffer
// as RGBA bytes, which both OpenGL and OpenGL ES read from any unorm attachment.
inline std::vector<uint8_t> read_back(GLuint t, int w, int h)
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
    return rgba;
}

inline GLenum image_format(const std::string& output_format)
{
    if (output_format == "r8") return GL_R8;
    if (output_format == "rgba8") return GL_RGBA8;
    fail("gl chain output format", quote(output_format) + " is not run here", "valid: r8, rgba8");
}

// ESSL 3.00 has no binding qualifiers (GLSL 450 and ESSL 310 do).
inline bool has_binding_qualifiers(const std::string& text)
{
    return text.rfind("#version 300 es", 0) != 0;
}

// What an ESSL 300 application does in place of binding qualifiers: each uniform block by
// its block name and each sampler (u_<name>, as the templates declare them) to its binding.
// `p` must be in use (glUniform1i sets the current program's uniforms).
inline void bind_by_name(GLuint p, const std::vector<codegen::resource>& resources)
{
    for (const codegen::resource& r : resources) {
        if (r.kind == codegen::resource_kind::uniform_buffer) {
            const GLuint block = glGetUniformBlockIndex(p, r.block.c_str());
            if (block != GL_INVALID_INDEX) glUniformBlockBinding(p, block, r.binding);
        } else if (r.kind == codegen::resource_kind::combined_image_sampler) {
            const GLint location = glGetUniformLocation(p, ("u_" + r.name).c_str());
            if (location >= 0) glUniform1i(location, GLint(r.binding));
        }
    }
}

// The G-buffer, noise and samplers every pass reads, uploaded once; and a history pass's two
// history images (rgba16f, cleared: no frame held), `history[read]` read this frame.
struct chain_textures {
    GLuint depth = 0, normals = 0, albedo = 0, motion = 0, noise = 0, clamp = 0, repeat = 0;
    GLuint history[2] = {0, 0};
    int read = 0;
};

// Binds `resources` of pass `name` at their bindings: its uniform block (bytes `uniforms`),
// the chain's textures, the previous pass's output `previous` and, for compute, `output`.
inline void bind_resources(objects& gl, const std::vector<codegen::resource>& resources, const std::string& name, const std::vector<uint8_t>& uniforms,
                           const chain_textures& t, GLuint previous, GLuint output, GLenum format)
{
    for (const codegen::resource& r : resources) {
        const GLuint unit = r.binding;
        if (r.kind == codegen::resource_kind::uniform_buffer) {
            glBindBufferBase(GL_UNIFORM_BUFFER, unit, gl.uniform_buffer(uniforms));
        } else if (r.kind == codegen::resource_kind::storage_image) {
            if (r.role == resource_role::history_output) {
                glBindImageTexture(unit, t.history[1 - t.read], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
                continue;
            }
            if (r.role != resource_role::output) fail("gl " + name, "binds storage image '" + r.name + "'", "valid: output, history_output (no diagnostics on GL)");
            glBindImageTexture(unit, output, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        } else if (r.kind == codegen::resource_kind::combined_image_sampler) {
            GLuint texture = 0, sampler = t.clamp;
            switch (r.role) {
            case resource_role::depth: texture = t.depth; break;
            case resource_role::normals: texture = t.normals; break;
            case resource_role::gbuffer_albedo: texture = t.albedo; break;
            case resource_role::noise: texture = t.noise, sampler = t.repeat; break;
            case resource_role::ao_input: texture = previous; break;
            case resource_role::history: texture = t.history[t.read]; break;
            case resource_role::motion: texture = t.motion; break;
            default: break;
            }
            if (!texture)
                fail("gl " + name, "reads '" + r.name + "', which this run has not",
                     "valid: depth, normals, albedo and motion vectors (a G-buffer with them), noise, ao_input, history");
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, texture);
            glBindSampler(unit, sampler);
        } else {
            fail("gl " + name, "binds " + std::string(codegen::to_name(r.kind)) + " '" + r.name + "'",
                 "valid: the vulkan binding model's resources (OpenGL has combined samplers only)");
        }
    }
}

// A fragment pass: the fullscreen triangle into `output` (w × h) -- and, the history pass,
// into `history` (the rgba16f history it writes, colour attachment 1) beside it.
inline void draw(objects& gl, GLuint output, int w, int h, GLuint history = 0)
{
    glBindFramebuffer(GL_FRAMEBUFFER, gl.framebuffer());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, output, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, history, 0);
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(history ? 2 : 1, buffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail("gl chain", history ? "an R8 and an RGBA16F colour attachment are not renderable together here" : "an R8 colour attachment is not renderable here",
             "valid: OpenGL 4.5, OpenGL ES 3.2, or ES 3.0 with EXT_color_buffer_half_float for a history pass");
    glDisable(GL_DITHER); // on by default: it may perturb the unorm conversion
    glViewport(0, 0, w, h);
    glBindVertexArray(gl.vertex_array());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
    glDrawBuffers(1, buffers);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace detail

// `p` is the plan the texts were emitted from (emitted_texts(p, target)): its passes,
// resources, output format, workgroups and pixels per invocation are what the runner binds
// and dispatches. `frames` holds each frame's inputs (plan.inputs of that frame's settings):
// the frames run one after the other on one G-buffer, a history pass keeping its history
// from frame to frame (two rgba16f images, cleared before the first, swapped after each), as
// a renderer's frame loop does; each frame's output is read back.
inline std::vector<chain_result> run_frames(const context& ctx, const codegen::plan& p, const std::vector<std::string>& texts, const gbuffer& g,
                                            const std::vector<chain_inputs>& frames)
{
    ctx.make_current();
    const variant& v = p.variant();
    if (has_prefilter_pass(v))
        fail("gl chain", to_name(v) + " has a depth MIP chain, which this runner does not build yet",
             "valid: variants without -mip<N> (the Vulkan harness runs those with one)");
    const std::vector<pass_kind>& kinds = p.passes();
    const std::vector<shader_stage> stages = codegen::stages(v);
    if (frames.empty()) fail("gl chain frames", "none given for " + to_name(v), "valid: one chain_inputs per frame, at least one");
    for (const chain_inputs& in : frames)
        if (texts.size() != kinds.size() * stages.size() || in.uniforms.size() != kinds.size())
            fail("gl chain", std::to_string(texts.size()) + " texts and " + std::to_string(in.uniforms.size()) + " uniform blocks for " + to_name(v),
                 "valid: " + std::to_string(kinds.size() * stages.size()) + " texts (" + std::to_string(stages.size()) + " per pass) and " +
                     std::to_string(kinds.size()) + " uniform blocks");
    const size_t pixels = size_t(g.width) * size_t(g.height);
    if (g.width < 1 || g.height < 1 || g.depth.size() != pixels || (!g.normals.empty() && g.normals.size() != 4 * pixels) ||
        (!g.albedo.empty() && g.albedo.size() != 4 * pixels) || (!g.motion.empty() && g.motion.size() != 2 * pixels))
        fail("gl chain", "G-buffer of " + std::to_string(g.width) + "x" + std::to_string(g.height) + " with " + std::to_string(g.depth.size()) + " depths",
             "valid: width × height depths, none or 4 × that normals and albedo values, none or 2 × that motion values");

    detail::objects gl;
    detail::chain_textures t;
    t.depth = gl.texture(g.width, g.height, GL_R32F, GL_RED, GL_FLOAT, g.depth.data());
    t.normals = g.normals.empty() ? 0 : gl.texture(g.width, g.height, GL_RGBA32F, GL_RGBA, GL_FLOAT, g.normals.data());
    t.albedo = g.albedo.empty() ? 0 : gl.texture(g.width, g.height, GL_RGBA32F, GL_RGBA, GL_FLOAT, g.albedo.data());
    t.motion = g.motion.empty() ? 0 : gl.texture(g.width, g.height, GL_RG32F, GL_RG, GL_FLOAT, g.motion.data());
    t.noise = gl.texture(frames[0].noise_size, frames[0].noise_size, GL_RGBA32F, GL_RGBA, GL_FLOAT, frames[0].noise.data());
    t.clamp = gl.sampler(GL_CLAMP_TO_EDGE), t.repeat = gl.sampler(GL_REPEAT);
    const auto [tw, th] = p.target_size(g.width, g.height);
    if (has_history_pass(v)) {
        const std::vector<uint16_t> zeros(size_t(tw) * size_t(th) * 4, 0); // 0 frames held
        for (GLuint& h : t.history) h = gl.texture(tw, th, GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, zeros.data());
    }
    const bool compute = v.stage == pipeline_stage::compute;
    const GLenum format = compute ? detail::image_format(codegen::output_format_of(v, p.source_options())) : GL_R8;

    // Each pass's program and output, made once for every frame.
    std::vector<GLuint> programs, outputs;
    std::vector<std::pair<int, int>> sizes;
    for (size_t i = 0; i < kinds.size(); ++i) {
        const pass_kind pass = kinds[i];
        const std::string name = p.name() + "." + names::name_of(pass_kind_names, pass, "pass");
        sizes.push_back(pass == pass_kind::upsample ? std::pair<int, int>{g.width, g.height} : std::pair<int, int>{tw, th});
        outputs.push_back(gl.texture(sizes.back().first, sizes.back().second, format, GL_RED, GL_UNSIGNED_BYTE, nullptr));
        const std::string& last = texts[i * stages.size() + stages.size() - 1]; // the compute or fragment shader
        programs.push_back(compute ? gl.program({{GL_COMPUTE_SHADER, &last}}, name)
                                   : gl.program({{GL_VERTEX_SHADER, &texts[i * 2]}, {GL_FRAGMENT_SHADER, &last}}, name));
    }
    std::vector<chain_result> results;
    for (const chain_inputs& in : frames) {
        GLuint previous = 0;
        for (size_t i = 0; i < kinds.size(); ++i) {
            const codegen::shader_plan& shader = p.pass_shader(i);
            const std::string name = p.name() + "." + names::name_of(pass_kind_names, kinds[i], "pass");
            const std::string& last = texts[i * stages.size() + stages.size() - 1];
            const auto [out_w, out_h] = sizes[i];
            glUseProgram(programs[i]);
            if (!detail::has_binding_qualifiers(last)) detail::bind_by_name(programs[i], shader.resources);
            detail::bind_resources(gl, shader.resources, name, in.uniforms[i], t, previous, outputs[i], format);
            if (compute) {
                const int k = shader.pixels_per_invocation;
                glDispatchCompute(detail::groups(out_w, k, shader.workgroup.first), detail::groups(out_h, k, shader.workgroup.second), 1);
                glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
            } else {
                detail::draw(gl, outputs[i], out_w, out_h, kinds[i] == pass_kind::history ? t.history[1 - t.read] : 0);
            }
            previous = outputs[i];
        }
        t.read = 1 - t.read; // the history written is the next frame's to read
        chain_result r;
        r.width = sizes.back().first, r.height = sizes.back().second;
        const std::vector<uint8_t> rgba = detail::read_back(previous, r.width, r.height);
        r.ao.resize(size_t(r.width) * size_t(r.height));
        for (size_t k = 0; k < r.ao.size(); ++k) r.ao[k] = rgba[4 * k] / 255.0f; // .r
        if (v.bent_normals) r.bent_normal = decode_bent_normals(rgba.data(), r.ao.size());
        results.push_back(std::move(r));
    }
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) fail("gl chain " + p.name(), "GL error " + std::to_string(error), "valid: none");
    return results;
}

// One frame of run_frames: a cleared history (a history pass writes this frame alone).
inline chain_result run(const context& ctx, const codegen::plan& p, const std::vector<std::string>& texts, const gbuffer& g, const chain_inputs& in)
{
    return run_frames(ctx, p, texts, g, {in}).front();
}

} // namespace aogen::gl
