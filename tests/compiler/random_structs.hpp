// tests/compiler/random_structs.hpp — test helper: seeded random struct descriptions.
//
// A deterministic generator of aogen::layout::block_desc values for the compiler-oracle
// tests. Its own splitmix64 stream (no std distributions, whose output differs between
// standard libraries), so a seed names the same struct everywhere and a failure message's
// seed reproduces it.
//
// What it produces, on purpose:
//   - every value type: float/int/uint, vec2..4, ivec2..4, uvec2..4, mat2..4 and matCxR;
//   - arrays of 1..5 elements of values and of structs;
//   - nesting two levels deep: the block holds structs (and arrays of them) that may hold
//     structs of their own;
//   - many 3-vectors followed by a scalar (the case std140/std430/Metal/HLSL disagree on);
//   - optionally a runtime-sized last member of the block (std430, scalar, msl).
#pragma once

#include <aogen/layout.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aogen_test {

// splitmix64: tiny, fast, and the same sequence on every platform.
class rng {
public:
    explicit rng(uint64_t seed) : state_(seed) {}

    uint64_t next()
    {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform enough in [0, n) for test generation (n is small).
    uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }
    // In [lo, hi].
    uint32_t between(uint32_t lo, uint32_t hi) { return lo + below(hi - lo + 1); }
    // True with probability percent/100.
    bool chance(uint32_t percent) { return below(100) < percent; }

private:
    uint64_t state_;
};

struct generator_options {
    bool structs = true;        // struct members and arrays of structs
    bool arrays = true;         // array members
    bool matrices = true;       // matCxR members
    bool runtime_array = false; // sometimes a runtime-sized last member of the block
    uint32_t min_members = 1;
    uint32_t max_members = 8;
};

namespace detail {

inline std::vector<std::string> scalar_types() { return {"float", "int", "uint"}; }

inline std::vector<std::string> vector_types()
{
    return {"vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4"};
}

inline std::vector<std::string> matrix_types()
{
    return {"mat2", "mat3", "mat4", "mat2x3", "mat2x4", "mat3x2", "mat3x4", "mat4x2", "mat4x3"};
}

inline std::vector<std::string> vec3_types() { return {"vec3", "ivec3", "uvec3"}; }

template <class T>
const T& pick(rng& r, const std::vector<T>& items)
{
    return items[r.below(static_cast<uint32_t>(items.size()))];
}

inline std::string value_type(rng& r, const generator_options& o)
{
    const uint32_t roll = r.below(100);
    if (roll < 30) return pick(r, scalar_types());
    if (roll < 70 || !o.matrices) return pick(r, vector_types());
    return pick(r, matrix_types());
}

// Members of one struct. `nested` are the struct types it may use (empty: none).
// `scalars_only`: a struct of scalars and scalar arrays (aligned to 4 everywhere).
inline std::vector<aogen::layout::member_desc> members(rng& r, const generator_options& o,
                                                       const std::vector<std::string>& nested,
                                                       uint32_t struct_percent = 20, bool scalars_only = false)
{
    using aogen::layout::member_desc;
    std::vector<member_desc> out;
    const uint32_t n = r.between(o.min_members, o.max_members);
    auto name = [&] { return "m" + std::to_string(out.size()); };
    auto maybe_array = [&](member_desc& m, uint32_t percent) {
        if (o.arrays && r.chance(percent)) m.count = r.between(1, 5);
    };
    while (out.size() < n) {
        const uint32_t roll = r.below(100);
        if (scalars_only) {
            member_desc s{name(), pick(r, scalar_types())};
            maybe_array(s, 25);
            out.push_back(s);
        } else if (roll < 20) { // the interesting pair: a 3-vector, then a scalar (sometimes an
            // array of them, sometimes a struct: Metal and std430 may align that differently)
            out.push_back({name(), pick(r, vec3_types())});
            member_desc s{name(), pick(r, scalar_types())};
            if (!nested.empty() && r.chance(25)) s.type = pick(r, nested);
            maybe_array(s, 15);
            out.push_back(s);
        } else if (roll < 20 + struct_percent && !nested.empty()) {
            member_desc s{name(), pick(r, nested)};
            maybe_array(s, 40);
            out.push_back(s);
        } else {
            member_desc v{name(), value_type(r, o)};
            maybe_array(v, 25);
            out.push_back(v);
        }
    }
    return out;
}

} // namespace detail

// A random block named "Blk" (level-2 struct types "Sia", "Sib", level-1 "Soa", "Sob").
// Same seed, same block.
inline aogen::layout::block_desc random_block(uint64_t seed, const generator_options& o = {})
{
    using namespace aogen::layout;
    rng r(seed * 0x2545F4914F6CDD1Dull + 1);
    block_desc block;
    std::vector<std::string> inner, outer; // level-2 structs (values only), level-1 structs (may hold level-2)
    if (o.structs) {
        const uint32_t inner_count = r.below(3), outer_count = inner_count ? r.below(3) : 0;
        for (uint32_t i = 0; i < inner_count; ++i) {
            const std::string name = std::string("Si") + char('a' + i);
            block.structs.push_back({name, detail::members(r, o, {}, 0, r.chance(35))});
            inner.push_back(name);
        }
        for (uint32_t i = 0; i < outer_count; ++i) {
            const std::string name = std::string("So") + char('a' + i);
            block.structs.push_back({name, detail::members(r, o, inner, 30)});
            outer.push_back(name);
        }
    }
    std::vector<std::string> usable = inner; // the block uses level-1 structs twice as often
    usable.insert(usable.end(), outer.begin(), outer.end());
    usable.insert(usable.end(), outer.begin(), outer.end());
    block.root = {"Blk", detail::members(r, o, usable)};
    if (o.runtime_array && r.chance(35)) {
        member_desc tail{"tail", r.chance(50) ? detail::pick(r, detail::scalar_types()) : detail::value_type(r, o), 0u};
        if (!usable.empty() && r.chance(25)) tail.type = detail::pick(r, usable);
        block.root.members.push_back(tail);
    }
    return block;
}

// The description as a one-line string, for failure messages.
inline std::string describe(const aogen::layout::block_desc& block)
{
    auto one = [](const aogen::layout::struct_desc& s) {
        std::string out = s.name + " {";
        for (const auto& m : s.members) {
            out += " " + m.type + " " + m.name;
            if (m.count) out += "[" + (*m.count ? std::to_string(*m.count) : std::string()) + "]";
            out += ";";
        }
        return out + " }";
    };
    std::string out;
    for (const auto& s : block.structs) out += "struct " + one(s) + " ";
    return out + "block " + one(block.root);
}

} // namespace aogen_test
