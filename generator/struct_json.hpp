// generator/struct_json.hpp — struct descriptions in and layouts out, as JSON.
//
// Input (the `aogen layout` STRUCT.json):
//   {"name": "Params",
//    "members": [{"name": "radius", "type": "float"},
//                {"name": "kernel", "type": "vec4", "count": 16},
//                {"name": "light",  "type": "Light"}],
//    "structs": [{"name": "Light", "members": [...]}]}
// `count` 0 is a runtime-sized array; types are GLSL spellings or a struct's name.
//
// Output: {"rules","name","size","align","members":[{"name","type","offset","size",
// "align","array_stride"?,"matrix_stride"?,"packed"?,"members"?}]}, a struct-typed
// member carrying its own members with offsets relative to that member's start.
#pragma once

#include <aogen_tools/json_reader.hpp>

#include <aogen/layout.hpp>

namespace aogen::cli {

using namespace tools; // the readers and writers the command line shares with the report (tools/)

inline layout::struct_desc struct_from_json(const json_reader& in)
{
    in.only_keys({"name", "members", "structs"});
    layout::struct_desc s;
    s.name = in.string("name");
    const json_reader members = in.array("members");
    for (size_t i = 0; i < members.size(); ++i) {
        const json_reader m = members.at(i);
        m.only_keys({"name", "type", "count"});
        layout::member_desc d{m.string("name"), m.string("type")};
        if (m.has("count")) d.count = m.unsigned_integer("count", 0, layout::max_array_count);
        s.members.push_back(d);
    }
    return s;
}

inline layout::block_desc block_from_json(const json_reader& in)
{
    layout::block_desc block;
    block.root = struct_from_json(in);
    if (in.has("structs")) {
        const json_reader structs = in.array("structs");
        for (size_t i = 0; i < structs.size(); ++i) block.structs.push_back(struct_from_json(structs.at(i)));
    }
    return block;
}

inline nlohmann::ordered_json members_to_json(const std::vector<layout::member_layout>& members)
{
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const layout::member_layout& m : members) {
        nlohmann::ordered_json j;
        j["name"] = m.name;
        j["type"] = m.type;
        if (m.count) j["count"] = *m.count;
        j["offset"] = m.offset;
        j["size"] = m.size;
        j["align"] = m.align;
        if (m.is_array()) j["array_stride"] = m.array_stride;
        if (m.matrix_stride) j["matrix_stride"] = m.matrix_stride;
        if (m.packed) j["packed"] = true;
        if (m.is_struct()) j["members"] = members_to_json(m.members);
        out.push_back(j);
    }
    return out;
}

inline nlohmann::ordered_json layout_to_json(const layout::struct_layout& l)
{
    nlohmann::ordered_json j;
    j["rules"] = layout::to_name(l.rule);
    j["name"] = l.name;
    j["size"] = l.size;
    j["align"] = l.align;
    j["members"] = members_to_json(l.members);
    return j;
}

} // namespace aogen::cli
