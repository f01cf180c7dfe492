// aogen/loops.hpp — the loops of a SPIR-V module's code, and the one that reads the images
// most: an AO pass's tap loop, whose size is what a pass costs per sample.
//
// WHAT
//   loops_of(words, name)      every structured loop of the module: its header block's id, how
//                              many instructions its blocks hold (nested loops' blocks
//                              included, each once: a static count, not what runs), how many
//                              of them read an image, and how deep it is nested
//   tap_loop_of(words, name)   the loop an AO pass spends its samples in: of the innermost
//                              loops that read an image (none of the loops inside them does),
//                              the one with the most image reads (ties: the most instructions).
//                              nullopt when no loop reads an image (everything unrolled)
//
// USAGE
//     #include <aogen/loops.hpp>   // CMake: target_link_libraries(... aogen::compiler)
//     namespace cc = aogen::compile;
//     std::optional<cc::loop> tap = cc::tap_loop_of(result.spirv, "gtao-… ao");
//     double per_tap = tap ? double(tap->instructions) / taps_per_iteration : 0;
//     // taps_per_iteration: the technique's (technique_desc::taps_per_iteration): GTAO and VBAO
//     // read a tap on each side per step, SSAO and SAO one per sample
//
// ERRORS
//   aogen::error naming `name`: a module that is not SPIR-V at the word level
//   (count_instructions' message), or a label, branch or merge instruction too short for its
//   operands.
//
// THE COUNT
//   SPIR-V's structured control flow makes a loop's blocks a closed set: a loop header (the
//   block with OpLoopMerge) names its merge block, and no branch inside the loop leaves it
//   other than to that merge block (or returns). So the loop's blocks are those reachable from
//   the header without passing through its merge block. Every instruction of them counts but
//   the declarations of structure no GPU executes -- OpLabel, OpSelectionMerge, OpLoopMerge:
//   arithmetic, memory access, branches and phis, as the driver receives them from an optimized
//   module (spirv-opt's performance passes inline every function). It is a static count: a
//   branch's two arms both count, a nested loop's body counts once, a vector operation counts
//   one (a 4 x 4 matrix times a vector is one instruction and sixteen multiply-adds): a measure
//   of what a change adds or removes, not of time.
//
// WHY
//   A pass's time on the device is the product of its taps and its cost per tap; the report
//   can time the first and count the second, and the count needs no device: an arithmetic
//   change shows here the moment it is made (issue 43's "instructions per tap").
#pragma once

#include "reflect.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace aogen::compile {

struct loop {
    uint32_t header = 0;       // the header block's result id
    uint32_t instructions = 0; // in the loop's blocks, nested loops' included (THE COUNT)
    uint32_t image_reads = 0;  // OpImageSample*, OpImageFetch, OpImage*Gather, OpImageRead among them
    uint32_t depth = 0;        // 0: in no other loop
    std::vector<uint32_t> nested; // the headers of the loops inside it, at any depth
};

namespace detail {

// One block of a function: its instructions, image reads, successors and, for a loop
// header, its merge block.
struct spirv_block {
    uint32_t instructions = 0, image_reads = 0, merge = 0;
    bool loop_header = false;
    std::vector<uint32_t> successors;
};

inline bool reads_image(uint32_t opcode)
{
    return (opcode >= spv::OpImageSampleImplicitLod && opcode <= spv::OpImageRead && opcode != spv::OpImageWrite) ||
           (opcode >= spv::OpImageSparseSampleImplicitLod && opcode <= spv::OpImageSparseRead &&
            opcode != spv::OpImageSparseTexelsResident);
}

// The words an instruction of `opcode` needs for the operands blocks_of reads; 1 for the rest.
inline uint32_t words_read(uint32_t opcode)
{
    switch (opcode) {
    case spv::OpLabel: case spv::OpBranch: return 2;
    case spv::OpSwitch: return 3;
    case spv::OpLoopMerge: case spv::OpBranchConditional: return 4;
    default: return 1;
    }
}

// Every block of every function, by its label's id.
inline std::map<uint32_t, spirv_block> blocks_of(const std::vector<uint32_t>& words, std::string_view name)
{
    count_instructions(words, name); // the word-level check
    std::map<uint32_t, spirv_block> blocks;
    spirv_block* current = nullptr;
    for (size_t i = 5; i < words.size(); i += words[i] >> 16) {
        const uint32_t opcode = words[i] & 0xffffu, length = words[i] >> 16;
        const uint32_t* w = &words[i];
        if (length < words_read(opcode))
            fail(name, "instruction at word " + std::to_string(i) + " (opcode " + std::to_string(opcode) + ") has " + std::to_string(length) + " words",
                 "valid: at least " + std::to_string(words_read(opcode)));
        if (opcode == spv::OpLabel) current = &blocks[w[1]];
        if (opcode == spv::OpFunction || opcode == spv::OpFunctionEnd) current = nullptr;
        if (!current) continue; // module-level instructions, a function's declaration and parameters
        if (opcode != spv::OpLabel && opcode != spv::OpSelectionMerge && opcode != spv::OpLoopMerge) ++current->instructions;
        if (reads_image(opcode)) ++current->image_reads;
        switch (opcode) {
        case spv::OpLoopMerge: current->loop_header = true, current->merge = w[1]; break;
        case spv::OpBranch: current->successors = {w[1]}; break;
        case spv::OpBranchConditional: current->successors = {w[2], w[3]}; break;
        case spv::OpSwitch:
            current->successors = {w[2]};
            for (uint32_t k = 3; k + 1 < length; k += 2) current->successors.push_back(w[k + 1]); // (literal, label) pairs
            break;
        default: break;
        }
    }
    return blocks;
}

// The blocks of the loop headed by `header`: reachable from it without entering `merge`.
inline std::set<uint32_t> loop_blocks(const std::map<uint32_t, spirv_block>& blocks, uint32_t header, uint32_t merge)
{
    std::set<uint32_t> seen{header};
    std::vector<uint32_t> pending{header};
    while (!pending.empty()) {
        const uint32_t id = pending.back();
        pending.pop_back();
        const auto it = blocks.find(id);
        if (it == blocks.end()) continue;
        for (uint32_t next : it->second.successors)
            if (next != merge && seen.insert(next).second) pending.push_back(next);
    }
    return seen;
}

} // namespace detail

// Every structured loop of the module (THE COUNT), in the order of their headers' ids.
inline std::vector<loop> loops_of(const std::vector<uint32_t>& words, std::string_view name = "SPIR-V")
{
    const std::map<uint32_t, detail::spirv_block> blocks = detail::blocks_of(words, name);
    std::vector<loop> loops;
    std::vector<std::set<uint32_t>> members;
    for (const auto& [id, b] : blocks) {
        if (!b.loop_header) continue;
        loop l;
        l.header = id;
        members.push_back(detail::loop_blocks(blocks, id, b.merge));
        for (uint32_t m : members.back()) {
            const auto it = blocks.find(m); // a branch to a label no block has: nothing to count
            if (it != blocks.end()) l.instructions += it->second.instructions, l.image_reads += it->second.image_reads;
        }
        loops.push_back(l);
    }
    for (size_t a = 0; a < loops.size(); ++a)
        for (size_t b = 0; b < loops.size(); ++b)
            if (a != b && members[b].count(loops[a].header)) ++loops[a].depth, loops[b].nested.push_back(loops[a].header);
    return loops;
}

// The AO pass's tap loop (WHAT); nullopt when no loop reads an image.
inline std::optional<loop> tap_loop_of(const std::vector<uint32_t>& words, std::string_view name = "SPIR-V")
{
    const std::vector<loop> loops = loops_of(words, name);
    auto reads = [&](uint32_t header) {
        for (const loop& l : loops)
            if (l.header == header) return l.image_reads > 0;
        return false;
    };
    std::optional<loop> best;
    for (const loop& l : loops) {
        if (l.image_reads == 0 || std::any_of(l.nested.begin(), l.nested.end(), reads)) continue; // not innermost
        if (!best || l.image_reads > best->image_reads || (l.image_reads == best->image_reads && l.instructions > best->instructions)) best = l;
    }
    return best;
}

} // namespace aogen::compile
