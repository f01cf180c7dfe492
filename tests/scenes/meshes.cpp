// aogen::scenes meshes: OBJ through assimp (triangulated, placed, relative to the scene file),
// Terragen .ter by our reader, file errors, and the built-in mesh scenes of assimp-testmodels.
#include "scene_tests.hpp"

#include <filesystem>
#include <fstream>

// One namespace per test file: the files of one executable share a translation unit
// (tests/CMakeLists.txt: a unity build), and their helpers must not meet.
namespace unity_meshes {

namespace {

namespace fs = std::filesystem;

// A fresh file under the temp directory (one name per test case: ctest may run them at once).
fs::path write_file(const std::string& name, const std::string& bytes)
{
    const fs::path dir = fs::temp_directory_path() / "aogen_scenes_tests";
    fs::create_directories(dir);
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

// The unit cube [0, 1]³ with quad faces, plus a line that must be dropped.
const char* const unit_cube_obj = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
l 1 7
)";

void check_box(const box& b, dvec3 lo, dvec3 hi)
{
    CHECK(b.lo.x == lo.x);
    CHECK(b.lo.y == lo.y);
    CHECK(b.lo.z == lo.z);
    CHECK(b.hi.x == hi.x);
    CHECK(b.hi.y == hi.y);
    CHECK(b.hi.z == hi.z);
}

} // namespace

TEST_CASE("a JSON mesh is triangulated and placed by scale, rotation about x and translation", "[scenes][mesh]")
{
    if (!have_assimp()) return;
    const fs::path obj = write_file("cube_placed.obj", unit_cube_obj);
    const fs::path json = write_file("cube_placed.json", R"({
        "name": "cube placed",
        "geometry": [
            {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]},
            {"type": "mesh", "file": "cube_placed.obj", "scale": 2, "rotate_x_degrees": 90, "translate": [1, 2, 3]}
        ],
        "camera": {"eye": [2, 1, 20], "target": [2, 1, 0], "up": [0, 1, 0], "width": 64, "height": 36}
    })");
    const scene s = load_scene(json.string()); // "cube_placed.obj" is found beside the JSON file
    REQUIRE(s.meshes.size() == 1);
    const mesh& m = s.meshes[0];
    CHECK(m.file == (json.parent_path() / "cube_placed.obj").string());
    CHECK(m.triangles.size() == 12); // 6 quads, the line dropped
    CHECK(m.vertices.size() == 8);   // identical vertices joined
    // (x, y, z) → 2·(x, −z, y) + (1, 2, 3): [0,1]³ → [1,3] × [0,2] × [3,5], exactly (quarter turn).
    check_box(bounds(m), {1, 0, 3}, {3, 2, 5});

    // Looking straight down: the cube's top (z = 5, view distance 15) in the middle, the floor
    // (geometry 0) around it; the mesh is geometry 1 (planes first).
    const gbuffer g = render_gbuffer(s);
    const size_t centre = size_t(18) * 64 + 32;
    CHECK(g.geometry[centre] == 1);
    CHECK(ulps(g.depth[centre], expected_depth(depth_convention::standard, s.camera.near, s.camera.far, 15)) <= 4);
    CHECK(g.geometry[0] == 0);
    CHECK(g.normals[4 * centre + 2] == Approx(1.0f));
}

TEST_CASE("a Terragen height field is read as assimp lays it out", "[scenes][mesh]")
{
    // SIZE 1, XPTS 3, YPTS 2, SCAL (2, 3, 4), ALTW height_scale 16384 (·/65536 = ¼), base 10.
    std::string ter = "TERRAGENTERRAIN ";
    const auto i16 = [&](int v) { ter += char(v & 0xff), ter += char((v >> 8) & 0xff); };
    const auto f32 = [&](float f) {
        uint32_t u;
        std::memcpy(&u, &f, 4);
        for (int k = 0; k < 4; ++k) ter += char((u >> (8 * k)) & 0xff);
    };
    ter += "SIZE", i16(1), i16(0), ter += "XPTS", i16(3), i16(0), ter += "YPTS", i16(2), i16(0);
    ter += "SCAL", f32(2), f32(3), f32(4);
    ter += "ALTW", i16(16384), i16(10);
    for (int h : {0, 4, 8, -4, 100, 0}) i16(h);
    ter += "EOF ";
    const fs::path p = write_file("tiny.ter", ter);
    const mesh m = load_mesh(p.string(), {1, 0, {0, 0, 1}}, "tiny");
    REQUIRE(m.vertices.size() == 6);
    REQUIRE(m.triangles.size() == 4); // (3 − 1)·(2 − 1) cells, two triangles each
    // Point (i, j) at (2i, 3j, (10 + h/4)·4) + (0, 0, 1).
    const double heights[6] = {0, 4, 8, -4, 100, 0};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            const dvec3 v = m.vertices[size_t(3 * j + i)];
            CHECK(v.x == 2.0 * i);
            CHECK(v.y == 3.0 * j);
            CHECK(v.z == (10 + heights[3 * j + i] / 4) * 4 + 1);
        }
    CHECK(m.triangles[0] == std::array<uint32_t, 3>{0, 3, 4});
    CHECK(m.triangles[1] == std::array<uint32_t, 3>{0, 4, 1});
}

TEST_CASE("a JSON mesh that cannot be loaded names the file and the field", "[scenes][mesh][json]")
{
    std::string m = message_of(R"({"geometry": [{"type": "mesh", "file": "no_such_mesh.obj"}]})", "models/scene.json");
    CHECK_THAT(m, Catch::Contains("models/scene.json.geometry[0].file") && Catch::Contains("'models/no_such_mesh.obj'") &&
                      Catch::Contains("cannot be read") && Catch::Contains("valid:"));
    if (!have_assimp()) return;
    const fs::path bad = write_file("not_a_mesh.glb", "this is not glTF");
    m = message_of(R"({"geometry": [{"type": "mesh", "file": ")" + bad.string() + R"("}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].file") && Catch::Contains(bad.string()) &&
                      Catch::Contains("format assimp reads"));
    m = message_of(R"({"geometry": [{"type": "mesh", "file": "a.obj", "scale": 0}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].scale") && Catch::Contains("out of range"));
    m = message_of(R"({"geometry": [{"type": "mesh", "file": "a.obj", "rotate_y_degrees": 90}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].rotate_y_degrees") && Catch::Contains("rotate_x_degrees"));
    m = message_of(R"({"geometry": [{"type": "mesh"}]})");
    CHECK_THAT(m, Catch::Contains("scene.json.geometry[0].file") && Catch::Contains("is missing"));
}

TEST_CASE("the built-in mesh scenes stand on the floor and fill a good part of the image", "[scenes][mesh][builtin]")
{
    // Triangle counts of the files (terrain: 512 × 512 cells, two triangles each).
    const std::pair<const char*, size_t> models[] = {{"engine", 121496}, {"teapots", 2976}, {"terrain", 524288}};
    for (const auto& [name, triangles] : models) {
        INFO(name);
        scene s;
        if (!builtin_or_skip(name, s)) continue;
        REQUIRE(s.meshes.size() == 1);
        CHECK(s.meshes[0].triangles.size() == triangles);
        const box b = bounds(s.meshes[0]);
        CHECK(b.lo.z == 0.0); // moved onto the floor
        CHECK(std::abs(b.lo.x + b.hi.x) < 1e-9 * (b.hi.x - b.lo.x)); // centred on the z axis
        const dvec3 diagonal = b.hi - b.lo;
        const double r = s.ao_radius / std::sqrt(truth::dot(diagonal, diagonal));
        CHECK(r >= 0.05);
        CHECK(r <= 0.1);
        const gbuffer g = render_gbuffer(s);
        const int mesh_id = int(s.planes.size()); // planes first, then the mesh
        size_t on_mesh = 0;
        for (int id : g.geometry) on_mesh += id == mesh_id;
        const double fraction = double(on_mesh) / g.geometry.size();
        INFO("mesh covers " << fraction << " of the image");
        CHECK(fraction >= 0.2);
        CHECK(fraction <= 0.95);
    }
}

TEST_CASE("a built-in scene whose model file is missing says to install assimp-testmodels", "[scenes][mesh][builtin]")
{
    CHECK_THROWS_WITH(detail::builtin_model("engine", "no/such/model.glb", {}),
                      Catch::Contains("built-in scene engine") && Catch::Contains("/usr/share/assimp/models/no/such/model.glb") &&
                          Catch::Contains("install assimp-testmodels"));
}

} // namespace unity_meshes
