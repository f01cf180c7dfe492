// aogen/vulkan/spirv_cache.hpp — SPIR-V of GLSL sources, compiled once per distinct text.
//
// WHAT
//   spirv_cache maps a shader's GLSL text (and stage) to its optimized, validated SPIR-V
//   (compile::compile, target spv). Variants that differ only in another pass share the
//   text of a pass (codegen.hpp, DETERMINISM), so a harness running many variants
//   compiles each distinct pass once. compile_all() compiles a batch on several threads
//   (compile() may run concurrently, compile.hpp THREADS): what the report does before it
//   builds any pipeline. Lookups and inserts are guarded by a mutex; a cache may be shared
//   by pass_pipelines on several threads.
//
//   A source is any value with the fields stage, name and glsl (codegen::shader_source is
//   one): the cache needs the compiler, not the code generator.
//
// USAGE
//     aogen::vulkan::spirv_cache cache;
//     cache.compile_all(sources);                          // every distinct text, on all cores
//     const std::vector<uint32_t>& words = cache.get(source);   // compiled here on a miss
//
// ERRORS
//   aogen::error from compile(), naming the shader (compile_all: the first failure, after
//   every thread has finished).
#pragma once

#include <aogen/compile.hpp>
#include <aogen/parallel.hpp>

#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace aogen::vulkan {

class spirv_cache {
public:
    // The SPIR-V of `s`, compiled now if no source of the same text and stage was.
    template <class Source>
    const std::vector<uint32_t>& get(const Source& s)
    {
        return get(s.stage, s.glsl, s.name);
    }
    const std::vector<uint32_t>& get(shader_stage stage, const std::string& glsl, const std::string& name)
    {
        const key k{stage, glsl};
        {
            std::lock_guard<std::mutex> lock(mutex_);
            auto it = words_.find(k);
            if (it != words_.end()) return it->second;
        }
        std::vector<uint32_t> words = compile::compile(glsl, stage, name, {compile::target::spv}).spirv;
        std::lock_guard<std::mutex> lock(mutex_);
        return words_.emplace(k, std::move(words)).first->second; // a concurrent twin's insert wins; both are equal
    }

    // Makes `words` the SPIR-V of `s`: for sources whose text is not GLSL (the HLSL round trip
    // compiles HLSL with compile::hlsl_to_spirv and runs it under the variant's own passes).
    template <class Source>
    void put(const Source& s, std::vector<uint32_t> words)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        words_[key{s.stage, s.glsl}] = std::move(words);
    }

    // Compiles every source not yet in the cache, on up to `threads` threads.
    template <class Source>
    void compile_all(const std::vector<Source>& sources, unsigned threads = std::thread::hardware_concurrency())
    {
        parallel_for(sources.size(), [&](size_t i) { get(sources[i]); }, threads);
    }

    size_t size() const
    {
        std::lock_guard<std::mutex> lock(mutex_);
        return words_.size();
    }

private:
    using key = std::pair<shader_stage, std::string>;
    mutable std::mutex mutex_;
    std::map<key, std::vector<uint32_t>> words_; // a map's elements never move: get()'s references stay valid
};

} // namespace aogen::vulkan
