// aogen/layout_writer.hpp — fills a buffer's bytes through a layout, by member path.
//
// Given a struct_layout from layout.hpp, a writer owns a zeroed byte buffer of the
// struct's size and stores values where the layout puts them. Padding is never written,
// so it stays zero, and the same values always give the same bytes.
//
//     aogen::layout::writer w(aogen::layout::compute(block, aogen::layout::rules::std140));
//     w.set("radius", 0.5f);
//     w.set("kernel", kernel);               // std::vector<vec4>: the whole array
//     w.set("lights[2].color", vec3{1, 0.5f, 0});
//     w.set("proj", projection);             // mat4, column-major
//     upload(w.bytes());
//
// Paths name members with '.', and array elements with [i]. A path to an array without
// an index sets every element from consecutive values. Values must match the member's
// type: the scalar kind (float, int, uint) and the number of components; anything else
// is an aogen::error naming the path, what it is and what was given.
//
// Bytes are little-endian, as every GPU API this library targets expects.
#pragma once

#include "error.hpp"
#include "layout.hpp"
#include "math.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::layout {

class writer {
public:
    // `runtime_elements`: how many elements a runtime-sized last member holds.
    explicit writer(struct_layout layout, uint32_t runtime_elements = 0)
        : layout_(std::move(layout)), runtime_elements_(runtime_elements)
    {
        uint64_t size = layout_.size;
        if (!layout_.members.empty() && layout_.members.back().is_runtime_array()) {
            const member_layout& last = layout_.members.back();
            size = std::max(size, uint64_t{last.offset} + uint64_t{last.array_stride} * runtime_elements);
        }
        if (size > max_block_bytes)
            fail("runtime elements of " + layout_.name, std::to_string(runtime_elements) + " make a " + std::to_string(size) + "-byte buffer",
                 "valid: buffers up to " + std::to_string(max_block_bytes) + " bytes");
        bytes_.assign(static_cast<size_t>(size), 0);
    }

    const struct_layout& layout() const { return layout_; }
    const std::vector<uint8_t>& bytes() const { return bytes_; }

    void set(std::string_view path, float v) { set_floats(path, &v, 1); }
    void set(std::string_view path, int32_t v) { set_ints(path, &v, 1); }
    void set(std::string_view path, uint32_t v) { set_uints(path, &v, 1); }
    void set(std::string_view path, vec2 v) { set_floats(path, &v.x, 2); }
    void set(std::string_view path, vec3 v) { set_floats(path, &v.x, 3); }
    void set(std::string_view path, vec4 v) { set_floats(path, &v.x, 4); }
    void set(std::string_view path, const mat4& m) { set_floats(path, m[0], 16); }
    void set(std::string_view path, const std::vector<vec4>& v) { set_floats(path, &v.data()->x, v.size() * 4); }
    void set(std::string_view path, const std::vector<float>& v) { set_floats(path, v.data(), v.size()); }

    void set_floats(std::string_view path, const float* values, size_t n)
    {
        store(path, scalar_type::float32, values, n);
    }
    void set_ints(std::string_view path, const int32_t* values, size_t n)
    {
        store(path, scalar_type::int32, values, n);
    }
    void set_uints(std::string_view path, const uint32_t* values, size_t n)
    {
        store(path, scalar_type::uint32, values, n);
    }

private:
    struct target {
        const member_layout* member = nullptr;
        uint32_t offset = 0;    // absolute offset of the member or of the indexed element
        uint32_t elements = 1;  // how many elements a value list covers
    };

    struct_layout layout_;
    uint32_t runtime_elements_ = 0;
    std::vector<uint8_t> bytes_;

    // Walks "a.b[3].c", adding each member's offset and each index times its stride.
    target resolve(std::string_view path) const
    {
        const std::vector<member_layout>* members = &layout_.members;
        target t;
        std::string_view rest = path;
        while (true) {
            const size_t end = rest.find_first_of(".[");
            const std::string_view name = rest.substr(0, end);
            t.member = nullptr;
            for (const member_layout& m : *members)
                if (m.name == name) t.member = &m;
            if (!t.member) fail(std::string(path), "no member named '" + std::string(name) + "'", "valid: " + member_names(*members));
            const member_layout& m = *t.member;
            t.offset += m.offset;
            t.elements = m.is_array() ? (m.is_runtime_array() ? runtime_elements_ : *m.count) : 1;
            rest = end == std::string_view::npos ? std::string_view() : rest.substr(end);
            if (!rest.empty() && rest[0] == '[') {
                const size_t close = rest.find(']');
                const uint32_t index = parse_index(path, rest.substr(1, close == std::string_view::npos ? close : close - 1));
                if (!m.is_array()) fail(std::string(path), quote(m.name) + " is not an array", "valid: index arrays only");
                if (index >= t.elements)
                    fail(std::string(path), "index " + std::to_string(index) + " is out of range", "valid: 0.." + std::to_string(t.elements) + " exclusive");
                t.offset += index * m.array_stride;
                t.elements = 1;
                rest = rest.substr(close + 1);
            }
            if (rest.empty()) return t;
            if (rest[0] != '.' || !m.is_struct() || t.elements != 1)
                fail(std::string(path), "cannot descend into '" + m.name + "'", "valid: name.member for a struct, name[i].member for an array of structs");
            members = &m.members;
            rest = rest.substr(1);
        }
    }

    static uint32_t parse_index(std::string_view path, std::string_view digits)
    {
        if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string_view::npos)
            fail(std::string(path), quote(digits) + " is not an array index", "valid: a decimal index in [ ]");
        return static_cast<uint32_t>(std::stoul(std::string(digits)));
    }

    static std::string member_names(const std::vector<member_layout>& members)
    {
        std::string names;
        for (const member_layout& m : members) names += (names.empty() ? "" : ", ") + m.name;
        return names;
    }

    template <class T>
    void store(std::string_view path, scalar_type given, const T* values, size_t n)
    {
        const target t = resolve(path);
        const member_layout& m = *t.member;
        if (m.is_struct()) fail(std::string(path), "is a struct " + m.type, "valid: set its members one by one");
        const value_type type = *m.value;
        const size_t expected = size_t(t.elements) * type.components();
        if (type.scalar != given)
            fail(std::string(path), "is " + m.type + ", given " + scalar_name(given) + " values",
                 std::string("valid: ") + scalar_name(type.scalar) + " values");
        if (n != expected)
            fail(std::string(path), "is " + m.type + (t.elements > 1 ? "[" + std::to_string(t.elements) + "]" : "") +
                                        ", given " + std::to_string(n) + " values",
                 "valid: " + std::to_string(expected) + " values");
        for (uint32_t e = 0; e < t.elements; ++e) {
            const uint32_t element = t.offset + e * m.array_stride;
            for (int c = 0; c < type.columns; ++c)
                for (int r = 0; r < type.rows; ++r)
                    put(element + c * m.matrix_stride + 4u * r, values[(size_t(e) * type.columns + c) * type.rows + r]);
        }
    }

    template <class T>
    void put(uint32_t offset, T value)
    {
        static_assert(sizeof(T) == 4, "every scalar is 4 bytes");
        uint32_t bits;
        std::memcpy(&bits, &value, 4);
        for (int i = 0; i < 4; ++i) bytes_[offset + i] = static_cast<uint8_t>(bits >> (8 * i));
    }
};

} // namespace aogen::layout
