// tests/fuzz/scene_fuzz.cpp — libFuzzer target: the scene files of the report,
// scenes::read_scene (scenes/include/aogen_scenes/scene.hpp).
//
// Each input is the text of a SCENE.json, read as "scene.json". A scene that parses (and
// so passed validate) gives the camera matrices the G-buffer and the AO passes are drawn
// with (world_to_view, projection_matrix): a camera that is bad in a way validate does not
// see reaches those. Nothing is ray-cast: Embree is the tracer, not the reader.
//
// NO FILES. A "mesh" entry makes read_scene load its "file" (load_mesh), and a fuzzer must
// not read whatever a mutated path names. So this target is built without assimp
// (AOGEN_SCENES_ASSIMP undefined, tests/fuzz/CMakeLists.txt): load_mesh then rejects every
// file but a Terragen .ter with an aogen::error, before opening it. The one path left, a
// .ter file, is skipped here: an input that names one is not parsed (and libFuzzer is told to
// keep it out of the corpus). Every check read_scene makes on a mesh entry before loading
// it ("scale", "rotate_x_degrees", "translate", a "file" that is no string) still runs.
// Relative mesh paths start at the scene file's directory; "scene.json" has none, so the
// path load_mesh tests is the "file" string itself, the string skipped here.
//
// Which failures are answers and which are findings: fuzz_support.hpp.
#include "fuzz_support.hpp"

#include <aogen_scenes/scene.hpp>

#ifdef AOGEN_SCENES_ASSIMP
#error "scene_fuzz.cpp must be built without assimp: it relies on load_mesh opening no file but a .ter"
#endif

namespace {

// Whether a geometry entry of `document` names a Terragen file, the one kind of mesh file
// load_mesh opens without assimp. It looks at every entry with a string "file", whatever
// its "type": a superset of what read_scene loads, which is all that skipping needs.
bool names_terragen_file(const nlohmann::json& document)
{
    if (!document.is_object()) return false;
    const auto geometry = document.find("geometry");
    if (geometry == document.end() || !geometry->is_array()) return false;
    for (const nlohmann::json& entry : *geometry) {
        if (!entry.is_object()) continue;
        const auto file = entry.find("file");
        if (file != entry.end() && file->is_string() && aogen::scenes::detail::ends_with_ter(file->get<std::string>()))
            return true;
    }
    return false;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace aogen;
    const std::string text = fuzz::text_of(data, size);
    bool skipped = false;
    fuzz::expect_errors([&] {
        // The parse read_scene starts with, done once more here to look inside: JSON it
        // rejects is rejected here with the same error.
        const nlohmann::json document = tools::json_reader::parse(text, "scene.json");
        if (names_terragen_file(document)) {
            skipped = true;
            return;
        }
        const scenes::scene s = scenes::read_scene(text, "scene.json");
        (void)s.camera.world_to_view();
        (void)s.camera.projection_matrix();
    });
    return skipped ? -1 : 0;
}
