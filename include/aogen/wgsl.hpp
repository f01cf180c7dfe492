// aogen/wgsl.hpp — WGSL through naga and Tint: SPIR-V → WGSL, every text validated twice,
// and WGSL → SPIR-V for the round trip.
//
// WHAT
//   SPIRV-Cross has no WGSL writer. naga (wgpu's shader translator, the npm package naga-wasm)
//   has, and Tint (Dawn's WGSL compiler, inside the npm package webgpu) is a second, independent
//   WGSL front end. Both run in Node.js, so this header runs wgsl/aogen_wgsl.mjs — one process
//   for a whole batch of shaders, over files in a temporary folder:
//     from_spirv(jobs)   SPIR-V → WGSL with naga; then naga parses and validates that text
//                        again and Tint compiles it (a compute shader also into a pipeline with
//                        the bind group layout WebGPU derives). A text either rejects is an
//                        aogen::error naming the shader, the tool and its message: no WGSL
//                        leaves here unvalidated.
//     to_spirv(texts)    WGSL → SPIR-V with naga (what the Vulkan harness runs to execute a
//                        WGSL text: vulkan/wgsl_round_trip.hpp)
//   The SPIR-V given to from_spirv must use WebGPU's binding model (separate textures and
//   samplers: codegen::options::model = binding_model::webgpu); naga's SPIR-V reader rejects
//   combined image samplers.
//
// WHERE THE TOOLS ARE
//   node: $AOGEN_NODE, else `node` on PATH (Debian 12's nodejs 18 runs both packages).
//   The script and its node_modules: $AOGEN_WGSL_TOOLS, else the folder CMake compiled in
//   (AOGEN_WGSL_TOOLS_DIR: the source tree's wgsl/, or the installed share/aogen/wgsl);
//   scripts/install-deps.sh installs the pinned packages there (npm ci). When either is
//   missing, the first call fails with one line saying what is missing and how to get it —
//   every other target works without them. With $AOGEN_WGSL_KEEP set, the temporary folders
//   (the inputs, outputs and messages of each batch) are left in $TMPDIR for a look.
//
// USAGE
//     std::vector<std::string> wgsl = aogen::wgsl::from_spirv({{"ssao-...-cs.ao.comp", aogen::shader_stage::compute, words}});
//     std::vector<std::vector<uint32_t>> back = aogen::wgsl::to_spirv({{"ssao-...-cs.ao.comp", aogen::shader_stage::compute, wgsl[0]}});
#pragma once

#include "error.hpp"
#include "stages.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace aogen::wgsl {

struct spirv_job {
    std::string name; // names the shader in messages
    shader_stage stage = shader_stage::compute;
    std::vector<uint32_t> spirv;
};
struct wgsl_job {
    std::string name;
    shader_stage stage = shader_stage::compute;
    std::string wgsl;
};

// Where node and aogen_wgsl.mjs are (WHERE THE TOOLS ARE).
struct tools {
    std::string node;
    std::string dir; // holds aogen_wgsl.mjs and node_modules/
};

namespace detail {

inline bool is_file(const std::string& path)
{
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

inline std::string on_path(const std::string& program)
{
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    std::stringstream in(dirs);
    for (std::string d; std::getline(in, d, ':');)
        if (!d.empty() && is_file(d + "/" + program) && ::access((d + "/" + program).c_str(), X_OK) == 0) return d + "/" + program;
    return "";
}

inline std::string read_all(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void write_all(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) fail("wgsl tools", "cannot write " + path, "valid: a writable temporary folder ($TMPDIR)");
}

// A temporary folder, removed with everything in it when this goes.
class scratch {
public:
    scratch()
    {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/aogen-wgsl-XXXXXX";
        std::vector<char> buf(pattern.begin(), pattern.end());
        buf.push_back('\0');
        if (!::mkdtemp(buf.data())) fail("wgsl tools", "cannot make a temporary folder in " + pattern + ": " + std::strerror(errno), "valid: a writable $TMPDIR");
        path_ = buf.data();
    }
    ~scratch()
    {
        if (std::getenv("AOGEN_WGSL_KEEP")) return; // for debugging the tools: the folder stays
        if (DIR* d = ::opendir(path_.c_str())) {
            while (const dirent* e = ::readdir(d))
                if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) ::unlink((path_ + "/" + e->d_name).c_str());
            ::closedir(d);
        }
        ::rmdir(path_.c_str());
    }
    scratch(const scratch&) = delete;
    scratch& operator=(const scratch&) = delete;
    // The path of file `name` in the folder.
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

inline std::string id_of(size_t i, shader_stage stage)
{
    std::string id = std::to_string(i);
    return std::string(6 - std::min<size_t>(6, id.size()), '0') + id + "." + file_extension(stage);
}

// Runs `args` (args[0] a path) to its end, its stderr -- with `stdout_too` its stdout as well
// -- written to file `log`: its exit status (-1: ended by a signal). An aogen::error when it
// cannot start (the log not writable, no process).
inline int run_process(std::vector<std::string> args, const std::string& log, bool stdout_too)
{
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    // Opened before the fork: between fork and exec the child calls only dup2 and execv.
    const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log_fd < 0) fail("wgsl tools", "cannot write " + log + ": " + std::strerror(errno), "valid: a writable temporary folder ($TMPDIR)");
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(log_fd);
        fail("wgsl tools", "cannot start " + args.at(0) + ": " + std::strerror(errno), "valid: a system that can run processes");
    }
    if (pid == 0) {
        if (stdout_too) ::dup2(log_fd, STDOUT_FILENO);
        ::dup2(log_fd, STDERR_FILENO); // dup2's copy does not inherit O_CLOEXEC
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(log_fd);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs `node aogen_wgsl.mjs <command> <dir>`; an aogen::error unless it exits 0.
inline void run(const tools& t, const std::string& command, const std::string& dir)
{
    const std::string script = t.dir + "/aogen_wgsl.mjs";
    const std::string log = dir + "/stderr.log";
    const int status = run_process({t.node, script, command, dir}, log, false);
    const std::string said = read_all(log);
    ::unlink(log.c_str());
    if (status == 0) return;
    std::string first = said.substr(0, said.find('\n'));
    fail("wgsl tools", "node " + script + " " + command + " failed" + (first.empty() ? "" : ": " + first),
         "valid: the packages of wgsl/package.json installed (scripts/install-deps.sh)");
}

inline std::string words_to_bytes(const std::vector<uint32_t>& words)
{
    std::string bytes;
    bytes.reserve(words.size() * 4);
    for (uint32_t w : words)
        for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>(w >> (8 * i)));
    return bytes;
}

inline std::vector<uint32_t> bytes_to_words(const std::string& bytes)
{
    std::vector<uint32_t> words(bytes.size() / 4);
    for (size_t i = 0; i < words.size(); ++i)
        for (int k = 0; k < 4; ++k) words[i] |= uint32_t(static_cast<unsigned char>(bytes[4 * i + k])) << (8 * k);
    return words;
}

// The tool's verdict on one shader: its output, or an aogen::error with its message.
inline std::string result_of(const scratch& s, const std::string& id, const std::string& output, const std::string& name)
{
    const std::string error_file = s.file(id + ".error"), out_file = s.file(id + output);
    if (is_file(error_file)) {
        std::string message = read_all(error_file);
        while (!message.empty() && message.back() == '\n') message.pop_back();
        throw error(name + ": " + message.substr(0, message.find('\n')) + " (valid: a shader both naga and Tint accept)" +
                    (message.find('\n') == std::string::npos ? "" : message.substr(message.find('\n'))));
    }
    if (!is_file(out_file)) fail(name, "the WGSL tools wrote no result for it", "valid: wgsl/aogen_wgsl.mjs as shipped");
    return read_all(out_file);
}

} // namespace detail

// The tools, or an aogen::error saying what is missing (WHERE THE TOOLS ARE).
inline tools find_tools()
{
    tools t;
    const char* node = std::getenv("AOGEN_NODE");
    t.node = node && *node ? std::string(node) : detail::on_path("node");
    if (t.node.empty() || !detail::is_file(t.node))
        fail("wgsl target", "needs Node.js, and there is no `node` on PATH" + std::string(node && *node ? " (nor at $AOGEN_NODE)" : ""),
             "valid: Debian's nodejs (scripts/install-deps.sh installs it), or the other targets");
    const char* dir = std::getenv("AOGEN_WGSL_TOOLS");
#if defined(AOGEN_WGSL_TOOLS_DIR)
    t.dir = dir && *dir ? std::string(dir) : std::string(AOGEN_WGSL_TOOLS_DIR);
#else
    t.dir = dir && *dir ? std::string(dir) : std::string();
#endif
    if (t.dir.empty() || !detail::is_file(t.dir + "/aogen_wgsl.mjs"))
        fail("wgsl target", "needs aogen's WGSL tools, and there is no aogen_wgsl.mjs in " + (t.dir.empty() ? std::string("(no folder set)") : t.dir),
             "valid: $AOGEN_WGSL_TOOLS naming the wgsl/ folder of aogen's source tree");
    for (const char* package : {"naga-wasm", "webgpu"})
        if (!detail::is_file(t.dir + "/node_modules/" + package + "/package.json"))
            fail("wgsl target", "needs the npm package " + std::string(package) + ", which is not installed in " + t.dir + "/node_modules",
                 "valid: `npm ci` in " + t.dir + " (scripts/install-deps.sh does it)");
    return t;
}

// SPIR-V (WebGPU's binding model) → WGSL, each text validated by naga and Tint.
inline std::vector<std::string> from_spirv(const std::vector<spirv_job>& jobs, const tools& t = find_tools())
{
    detail::scratch s;
    for (size_t i = 0; i < jobs.size(); ++i)
        detail::write_all(s.file(detail::id_of(i, jobs[i].stage) + ".spv"), detail::words_to_bytes(jobs[i].spirv));
    detail::run(t, "from-spirv", s.path());
    detail::run(t, "tint", s.path()); // a process of its own (aogen_wgsl.mjs says why)
    std::vector<std::string> out;
    for (size_t i = 0; i < jobs.size(); ++i) out.push_back(detail::result_of(s, detail::id_of(i, jobs[i].stage), ".wgsl", jobs[i].name));
    return out;
}

// WGSL → SPIR-V with naga.
inline std::vector<std::vector<uint32_t>> to_spirv(const std::vector<wgsl_job>& jobs, const tools& t = find_tools())
{
    detail::scratch s;
    for (size_t i = 0; i < jobs.size(); ++i) detail::write_all(s.file(detail::id_of(i, jobs[i].stage) + ".wgsl"), jobs[i].wgsl);
    detail::run(t, "to-spirv", s.path());
    std::vector<std::vector<uint32_t>> out;
    for (size_t i = 0; i < jobs.size(); ++i)
        out.push_back(detail::bytes_to_words(detail::result_of(s, detail::id_of(i, jobs[i].stage), ".spv.out", jobs[i].name)));
    return out;
}

// One pass of a chain for run_on_dawn: its WGSL (a compute shader; or a fragment shader and
// the vertex shader it is drawn with), its output's size, the pixels one invocation writes
// (aogen::pixels_per_invocation), its uniform bytes and, for the last pass of a -mbg
// variant, the binding it reads the albedo G-buffer at.
struct dawn_pass {
    std::string wgsl;
    std::string vertex_wgsl; // empty for a compute pass
    int width = 0, height = 0;
    int pixels_per_invocation = 1;
    std::vector<std::vector<uint8_t>> uniforms; // per frame (run_on_dawn runs as many frames as these)
    int albedo_binding = -1; // -1: the pass reads no albedo
    // A history pass (-hist, -histmv): where it reads the history and writes the next (two
    // rgba16float images of its output's size, cleared, swapped after each frame); -1: none
    // (history_output_binding -1 beside a history binding: a fragment pass, whose colour target 1 it is).
    int history_binding = -1, history_output_binding = -1;
    int motion_binding = -1; // -1: the pass reads no motion vectors
};

// The result of run_on_dawn per frame: the last pass's output (.r, one byte a pixel, row-major), its
// whole texels (4 bytes each for compute passes' rgba8unorm, 1 for fragment passes' r8unorm)
// and the device Dawn ran it on.
struct dawn_result {
    std::vector<uint8_t> ao;
    std::vector<uint8_t> texels;
    std::string device;
};

// Executes a chain's WGSL on a real WebGPU implementation: Dawn (npm webgpu) on its
// OpenGL ES backend, Tint's GLSL ES on Mesa's llvmpipe (EGL surfaceless) — Dawn refuses
// lavapipe as a Vulkan device. Inputs as aogen::gbuffer and chain_inputs hold them: depth
// (W×H floats), normals and albedo (W×H×4 floats each, or none), motion vectors (W×H×2, or
// none), the noise tile (N×N RGBA32F bytes). Bindings are the webgpu model's (bindings.hpp).
// Runs as many frames as the passes have uniform blocks, one after the other on one device (a
// history pass's history kept from frame to frame), and returns every frame's output. An
// aogen::error with Dawn's message when it fails.
inline std::vector<dawn_result> run_on_dawn(int width, int height, const std::vector<float>& depth, const std::vector<float>& normals,
                                            const std::vector<float>& albedo, const std::vector<float>& motion, int noise_size,
                                            const std::vector<uint8_t>& noise, const std::vector<dawn_pass>& passes, const tools& t = find_tools())
{
    detail::scratch s;
    const auto floats = [](const std::vector<float>& f) { return std::string(reinterpret_cast<const char*>(f.data()), f.size() * sizeof(float)); };
    const size_t frames = passes.empty() ? 0 : passes.front().uniforms.size();
    if (frames == 0) fail("wgsl on dawn", "no frame to run", "valid: each pass's uniforms for at least one frame");
    std::string chain = "gbuffer " + std::to_string(width) + " " + std::to_string(height) + "\nnoise " + std::to_string(noise_size) + "\nframes " +
                        std::to_string(frames) + "\n";
    detail::write_all(s.file("depth.f32"), floats(depth));
    if (!normals.empty()) detail::write_all(s.file("normals.f32"), floats(normals));
    if (!albedo.empty()) detail::write_all(s.file("albedo.f32"), floats(albedo));
    if (!motion.empty()) detail::write_all(s.file("motion.f32"), floats(motion));
    detail::write_all(s.file("noise.f32"), std::string(noise.begin(), noise.end()));
    for (size_t i = 0; i < passes.size(); ++i) {
        const std::string file = "pass" + std::to_string(i) + ".wgsl";
        detail::write_all(s.file(file), passes[i].wgsl);
        const std::string vertex = passes[i].vertex_wgsl.empty() ? "" : "pass" + std::to_string(i) + ".vert.wgsl";
        if (!vertex.empty()) detail::write_all(s.file(vertex), passes[i].vertex_wgsl);
        if (passes[i].uniforms.size() != frames)
            fail("wgsl on dawn", "pass " + std::to_string(i) + " has uniforms for " + std::to_string(passes[i].uniforms.size()) + " frames",
                 "valid: every pass the same number, " + std::to_string(frames));
        for (size_t f = 0; f < frames; ++f)
            detail::write_all(s.file("uniforms" + std::to_string(i) + (f == 0 ? "" : "_" + std::to_string(f)) + ".bin"),
                              std::string(passes[i].uniforms[f].begin(), passes[i].uniforms[f].end()));
        chain += "pass " + file + " " + std::to_string(passes[i].width) + " " + std::to_string(passes[i].height) + " " +
                 std::to_string(passes[i].pixels_per_invocation) + (vertex.empty() ? "" : " " + vertex) + "\n";
        if (passes[i].albedo_binding >= 0) {
            if (albedo.empty()) fail("wgsl on dawn", "pass " + std::to_string(i) + " reads the albedo G-buffer, and none was given", "valid: W×H×4 albedo floats");
            chain += "albedo " + std::to_string(passes[i].albedo_binding) + "\n";
        }
        if (passes[i].history_binding >= 0)
            chain += "history " + std::to_string(passes[i].history_binding) + " " + std::to_string(passes[i].history_output_binding) + "\n";
        if (passes[i].motion_binding >= 0) {
            if (motion.empty()) fail("wgsl on dawn", "pass " + std::to_string(i) + " reads motion vectors, and none were given", "valid: W×H×2 motion floats");
            chain += "motion " + std::to_string(passes[i].motion_binding) + "\n";
        }
    }
    detail::write_all(s.file("chain.txt"), chain);
    detail::run(t, "run", s.path());
    if (detail::is_file(s.file("run.error"))) {
        std::string message = detail::read_all(s.file("run.error"));
        while (!message.empty() && message.back() == '\n') message.pop_back();
        fail("wgsl on dawn", message, "valid: a chain Dawn's OpenGL ES backend runs");
    }
    std::vector<dawn_result> out;
    for (size_t f = 0; f < frames; ++f) {
        const std::string ao = detail::read_all(s.file("out" + std::to_string(f) + ".bin")), texels = detail::read_all(s.file("texels" + std::to_string(f) + ".bin"));
        out.push_back({std::vector<uint8_t>(ao.begin(), ao.end()), std::vector<uint8_t>(texels.begin(), texels.end()), detail::read_all(s.file("device.txt"))});
    }
    return out;
}

} // namespace aogen::wgsl
