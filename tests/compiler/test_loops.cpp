// loops.hpp: a SPIR-V module's loops and an AO pass's tap loop.
//
// The oracle of the count is a module written by hand in SPIR-V assembly (spirv-as through
// SPIRV-Tools), whose blocks' instructions are counted in the comments beside them; the
// templates' loops are checked against their GLSL's structure (which loop reads the taps, and
// how deep it sits), compiled and optimized as every shader aogen ships.

#include <aogen/codegen.hpp>
#include <aogen/compile.hpp>
#include <aogen/loops.hpp>
#include <aogen/matrix.hpp>

#include <catch2/catch.hpp>

#include <spirv-tools/libspirv.hpp>

#include <string>
#include <vector>

namespace unity_test_loops {

namespace cc = aogen::compile;

namespace {

std::vector<uint32_t> assemble(const std::string& text)
{
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_0);
    std::vector<uint32_t> words;
    REQUIRE(tools.Assemble(text, &words));
    return words;
}

// An outer loop holding an inner one that reads an image twice, then an image read outside any
// loop, then a second loop that reads once. Instructions per block in the comments (THE COUNT:
// OpLabel and the merge declarations do not count).
const char* const nested_loops = R"(
               OpCapability Shader
               OpMemoryModel Logical GLSL450
               OpEntryPoint GLCompute %main "main"
               OpExecutionMode %main LocalSize 1 1 1
       %void = OpTypeVoid
         %fn = OpTypeFunction %void
       %bool = OpTypeBool
       %true = OpConstantTrue %bool
      %float = OpTypeFloat 32
        %int = OpTypeInt 32 1
      %v2int = OpTypeVector %int 2
    %v4float = OpTypeVector %float 4
      %int_0 = OpConstant %int 0
      %coord = OpConstantComposite %v2int %int_0 %int_0
      %image = OpTypeImage %float 2D 0 0 0 1 Unknown
  %image_ptr = OpTypePointer UniformConstant %image
        %tex = OpVariable %image_ptr UniformConstant
       %main = OpFunction %void None %fn
      %entry = OpLabel
               OpBranch %outer
      %outer = OpLabel                                   ; outer header: 1
               OpLoopMerge %outer_merge %outer_continue None
               OpBranch %inner
      %inner = OpLabel                                   ; inner header: 1
               OpLoopMerge %inner_merge %inner_continue None
               OpBranchConditional %true %inner_body %inner_merge
 %inner_body = OpLabel                                   ; 4, two reads
         %i1 = OpLoad %image %tex
          %a = OpImageFetch %v4float %i1 %coord
          %b = OpImageFetch %v4float %i1 %coord
               OpBranch %inner_continue
%inner_continue = OpLabel                                ; 1
               OpBranch %inner
%inner_merge = OpLabel                                   ; 1
               OpBranchConditional %true %outer_continue %outer_merge
%outer_continue = OpLabel                                ; 1
               OpBranch %outer
%outer_merge = OpLabel                                   ; in no loop
         %i2 = OpLoad %image %tex
          %c = OpImageFetch %v4float %i2 %coord
               OpBranch %second
     %second = OpLabel                                   ; second header: 1
               OpLoopMerge %second_merge %second_continue None
               OpBranchConditional %true %second_body %second_merge
%second_body = OpLabel                                   ; 3, one read
         %i3 = OpLoad %image %tex
          %d = OpImageFetch %v4float %i3 %coord
               OpBranch %second_continue
%second_continue = OpLabel                               ; 1
               OpBranch %second
%second_merge = OpLabel
               OpReturn
               OpFunctionEnd
)";

// The optimized SPIR-V of `v`'s AO pass, as the report and every runner compile it.
std::vector<uint32_t> ao_pass_spirv(const aogen::variant& v)
{
    for (const aogen::codegen::shader_source& s : aogen::codegen::generate(aogen::codegen::make_plan(v)))
        if (s.pass == aogen::pass_kind::ao && s.stage != aogen::shader_stage::vertex)
            return cc::compile(s.glsl, s.stage, s.name, {cc::target::spv}).spirv;
    FAIL("no AO pass in " << aogen::to_name(v));
    return {};
}

} // namespace

TEST_CASE("loops: each loop's blocks counted, nested loops inside, the tap loop the innermost that reads most", "[loops]")
{
    const std::vector<uint32_t> words = assemble(nested_loops);
    const std::vector<cc::loop> loops = cc::loops_of(words, "nested loops");
    REQUIRE(loops.size() == 3);
    // By header id: outer, inner, second (the assembler numbers ids in order of first mention).
    const cc::loop& outer = loops[0];
    const cc::loop& inner = loops[1];
    const cc::loop& second = loops[2];
    CHECK(outer.instructions == 1 + (1 + 4 + 1) + 1 + 1);
    CHECK(outer.image_reads == 2);
    CHECK(outer.depth == 0);
    CHECK(outer.nested == std::vector<uint32_t>{inner.header});
    CHECK(inner.instructions == 1 + 4 + 1);
    CHECK(inner.image_reads == 2);
    CHECK(inner.depth == 1);
    CHECK(inner.nested.empty());
    CHECK(second.instructions == 1 + 3 + 1);
    CHECK(second.image_reads == 1);
    CHECK(second.depth == 0);

    const std::optional<cc::loop> tap = cc::tap_loop_of(words, "nested loops");
    REQUIRE(tap);
    CHECK(tap->header == inner.header);
}

TEST_CASE("loops: a module without a loop that reads has no tap loop, and one that is not SPIR-V is refused by name", "[loops]")
{
    std::string no_reads = nested_loops;
    for (const char* read : {"%a = OpImageFetch", "%b = OpImageFetch", "%d = OpImageFetch"})
        no_reads.replace(no_reads.find(read), std::string(read).size(), std::string(read).substr(0, 5) + "OpLoad %image %tex ;");
    // the reads' lines now load twice into one id: still well-formed words, no read in a loop
    const std::vector<uint32_t> words = assemble(no_reads);
    CHECK(cc::loops_of(words).size() == 3);
    CHECK_FALSE(cc::tap_loop_of(words));
    try {
        cc::tap_loop_of({1, 2, 3}, "gtao-… ao");
        FAIL("a 3-word module was accepted");
    } catch (const aogen::error& e) {
        CHECK(std::string(e.what()).find("gtao-… ao") != std::string::npos);
    }
    // The module's last instruction (OpFunctionEnd) made a one-word OpBranch: its target
    // would be read past the module's end.
    std::vector<uint32_t> short_branch = words;
    short_branch.back() = (1u << 16) | spv::OpBranch;
    try {
        cc::loops_of(short_branch, "vbao-… ao");
        FAIL("a one-word OpBranch was read");
    } catch (const aogen::error& e) {
        CHECK(std::string(e.what()).find("vbao-… ao: instruction at word") != std::string::npos);
        CHECK(std::string(e.what()).find("valid: at least 2") != std::string::npos);
    }
}

TEST_CASE("loops: every technique's tap loop is the loop of its samples (slice techniques: the steps, inside the slices)", "[loops]")
{
    for (const char* name : {"ssao-s16-half-bilateral-gbufworld-std-persp-cs", "sao-s16-half-denoise-gbufworld-std-persp-cs",
                             "gtao-2x2-half-denoise-gbufworld-std-persp-cs", "vbao-3x3-half-bilateral-gbufworld-std-persp-cs",
                             "gtao-3x3-full-denoise-gbufview-std-persp-fs"}) {
        const aogen::variant v = aogen::variant_from_name(name);
        const std::vector<uint32_t> words = ao_pass_spirv(v);
        const std::optional<cc::loop> tap = cc::tap_loop_of(words, name);
        INFO(name);
        REQUIRE(tap);
        const bool slices = v.tech == aogen::technique::gtao || v.tech == aogen::technique::vbao;
        CHECK(tap->depth == (slices ? 1u : 0u));
        CHECK(tap->image_reads >= (slices ? 2u : 1u)); // a tap on each side of a step; one per sample
        CHECK(tap->instructions > 20);
    }
}

} // namespace unity_test_loops
