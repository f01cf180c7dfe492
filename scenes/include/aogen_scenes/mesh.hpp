// aogen_scenes/mesh.hpp — triangle meshes for scenes: read from a model file with assimp (or,
// for Terragen .ter height fields, by a reader of our own) and placed in world space.
//
// WHAT
//   mesh                        world-space vertices (double) and triangles (uint32 index
//                               triples): exactly what truth::scene::add_triangles takes.
//   mesh_placement              world = translate + R_x(rotate_x_degrees) · (scale · v), where
//                               v is the file's vertex after its own node transforms. 90° about
//                               x turns a y-up model (glTF, most DCC exports) z-up.
//   load_mesh(path, placement, subject)
//                               every triangle of every mesh in the file, node transforms
//                               applied (aiProcess_PreTransformVertices), polygons triangulated,
//                               identical vertices joined, points and lines dropped. `subject`
//                               (a JSON field, "scene.json.geometry[2].file") starts every error.
//   bounds(m), translate(m, t)  the axis-aligned bounds (of a mesh or of points); moving a
//                               mesh in place.
//
// USAGE
//     aogen::scenes::mesh m = aogen::scenes::load_mesh("engine.glb", {0.001, 90, {}}, "engine");
//     aogen::scenes::box b = aogen::scenes::bounds(m);
//     tracer.add_triangles(m.vertices, m.triangles);
//
// WHY
//   * Terragen: assimp 5.2 (Debian 12) fails on every .ter file with "End of file or read
//     limit was reached" (assimp#3093, fixed in 5.3), and the format is a header and a grid of
//     int16 heights, so .ter files are read here, laid out as assimp's importer does: point
//     (i, j) at (i·sx, j·sy, (base + h·height_scale/65536)·sz), z up, each cell split into
//     the triangles (i,j)(i,j+1)(i+1,j+1) and (i,j)(i+1,j+1)(i+1,j).
//   * assimp is optional: without it (AOGEN_SCENES_ASSIMP not defined, scenes/
//     CMakeLists.txt) every other format is an error that says to install libassimp-dev.
//   * Rotation uses random::cos_sin_turns: exact for quarter turns and the same bits on every
//     platform, so a mesh scene is the same geometry everywhere.
#pragma once

#include <aogen/error.hpp>
#include <aogen/random.hpp>
#include <aogen_truth/tracer.hpp>

#ifdef AOGEN_SCENES_ASSIMP
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace aogen::scenes {

using dvec3 = truth::vec3; // world space in double: scenes may sit far from the origin

struct box { dvec3 lo, hi; }; // axis-aligned

struct mesh {
    std::string file; // where it came from, for messages ("" for generated meshes)
    std::vector<dvec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles;
};

struct mesh_placement {
    double scale = 1;
    double rotate_x_degrees = 0;
    dvec3 translate;

    dvec3 apply(dvec3 v) const
    {
        const random::cos_sin r = random::cos_sin_turns(rotate_x_degrees / 360.0);
        const dvec3 s = scale * v;
        return translate + dvec3{s.x, r.c * s.y - r.s * s.z, r.s * s.y + r.c * s.z};
    }
};

inline box bounds(const std::vector<dvec3>& points)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    box b{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const dvec3& v : points) {
        b.lo = {std::min(b.lo.x, v.x), std::min(b.lo.y, v.y), std::min(b.lo.z, v.z)};
        b.hi = {std::max(b.hi.x, v.x), std::max(b.hi.y, v.y), std::max(b.hi.z, v.z)};
    }
    return b;
}

inline box bounds(const mesh& m) { return bounds(m.vertices); }

inline void translate(mesh& m, dvec3 t)
{
    for (dvec3& v : m.vertices) v = v + t;
}

namespace detail {

inline std::vector<unsigned char> read_bytes(const std::string& path, const std::string& subject)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(subject, quote(path) + " cannot be read", "valid: an existing, readable mesh file");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline bool ends_with_ter(const std::string& path)
{
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".ter";
}

// Little-endian reads (Terragen files are little-endian whatever the host).
inline uint32_t le_u32(const unsigned char* p) { return p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24; }
inline int16_t le_i16(const unsigned char* p) { return int16_t(uint16_t(p[0] | p[1] << 8)); }
inline float le_f32(const unsigned char* p)
{
    const uint32_t u = le_u32(p);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}

// Terragen .ter: "TERRAGENTERRAIN ", then 4-character chunks: SIZE, XPTS, YPTS (int16 and
// 2 bytes of padding), SCAL (3 floats, metres per point; default 30), CRAD (float), CRVM
// (uint8 and 3 bytes), ALTW (int16 height_scale, int16 base_height, xpts·ypts int16 heights,
// rows of x), EOF. Curvature (CRAD, CRVM) is ignored, as assimp does.
inline mesh read_terragen(const std::string& path, const std::string& subject)
{
    const std::vector<unsigned char> d = read_bytes(path, subject);
    const auto bad = [&](const std::string& why) {
        fail(subject, quote(path) + " is not a Terragen terrain: " + why, "valid: a .ter file written by Terragen");
    };
    if (d.size() < 16 || std::memcmp(d.data(), "TERRAGENTERRAIN ", 16) != 0) bad("no TERRAGENTERRAIN header");
    unsigned xpts = 0, ypts = 0;
    float scal[3] = {30, 30, 30};
    size_t at = 16;
    const auto need = [&](size_t n) {
        if (d.size() - at < n) bad("it ends inside a chunk");
    };
    while (at + 4 <= d.size()) {
        const std::string id(reinterpret_cast<const char*>(&d[at]), 4);
        at += 4;
        if (id == "SIZE" || id == "XPTS" || id == "YPTS") {
            need(4);
            const unsigned v = unsigned(le_i16(&d[at])) & 0xffffu;
            if (id == "SIZE") xpts = xpts ? xpts : v + 1, ypts = ypts ? ypts : v + 1;
            if (id == "XPTS") xpts = v;
            if (id == "YPTS") ypts = v;
            at += 4;
        } else if (id == "SCAL") {
            need(12);
            for (int k = 0; k < 3; ++k) scal[k] = le_f32(&d[at + 4 * k]);
            at += 12;
        } else if (id == "CRAD" || id == "CRVM") {
            need(4);
            at += 4;
        } else if (id == "ALTW") {
            need(4);
            const double height_scale = le_i16(&d[at]) / 65536.0, base = le_i16(&d[at + 2]);
            at += 4;
            if (xpts < 2 || ypts < 2) bad("fewer than 2×2 points");
            need(size_t(xpts) * ypts * 2);
            mesh m;
            m.file = path;
            for (unsigned j = 0; j < ypts; ++j)
                for (unsigned i = 0; i < xpts; ++i, at += 2)
                    m.vertices.push_back({double(i) * scal[0], double(j) * scal[1],
                                          (base + le_i16(&d[at]) * height_scale) * scal[2]});
            for (uint32_t j = 0; j + 1 < ypts; ++j)
                for (uint32_t i = 0; i + 1 < xpts; ++i) {
                    const uint32_t a = j * xpts + i, b = a + xpts; // b: the next row
                    m.triangles.push_back({a, b, b + 1});
                    m.triangles.push_back({a, b + 1, a + 1});
                }
            return m;
        } else if (id == "EOF ") {
            break;
        } else {
            bad("unknown chunk \"" + id + "\"");
        }
    }
    bad("no ALTW (heights) chunk");
    return {}; // not reached
}

#ifdef AOGEN_SCENES_ASSIMP
inline mesh read_with_assimp(const std::string& path, const std::string& subject)
{
    read_bytes(path, subject); // a missing file gets our message rather than assimp's
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* s = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                                   aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    const std::string valid = "valid: a file with triangles or polygons (points and lines are dropped) in a format assimp "
                              "reads: .obj, .gltf, .glb, .dae, .ply, .stl, .fbx, ...";
    if (!s || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        fail(subject, quote(path) + " cannot be loaded by assimp: " + importer.GetErrorString(), valid);
    mesh m;
    m.file = path;
    for (unsigned i = 0; i < s->mNumMeshes; ++i) {
        const aiMesh& am = *s->mMeshes[i];
        const auto first = uint32_t(m.vertices.size());
        for (unsigned v = 0; v < am.mNumVertices; ++v)
            m.vertices.push_back({am.mVertices[v].x, am.mVertices[v].y, am.mVertices[v].z});
        for (unsigned f = 0; f < am.mNumFaces; ++f) {
            const aiFace& face = am.mFaces[f];
            if (face.mNumIndices != 3) continue; // points and lines (when SortByPType kept them)
            m.triangles.push_back({first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
        }
    }
    return m;
}
#endif

} // namespace detail

// Reads `path` and places it; errors start with `subject` and name the file.
inline mesh load_mesh(const std::string& path, const mesh_placement& placement, const std::string& subject)
{
#ifdef AOGEN_SCENES_ASSIMP
    mesh m = detail::ends_with_ter(path) ? detail::read_terragen(path, subject) : detail::read_with_assimp(path, subject);
#else
    if (!detail::ends_with_ter(path))
        fail(subject, quote(path) + " needs assimp, which aogen::scenes was built without",
             "valid: a Terragen .ter file, or rebuild with libassimp-dev installed");
    mesh m = detail::read_terragen(path, subject);
#endif
    if (m.triangles.empty())
        fail(subject, quote(path) + " has no triangles", "valid: a mesh file with at least one triangle");
    for (dvec3& v : m.vertices) v = placement.apply(v);
    return m;
}

} // namespace aogen::scenes
