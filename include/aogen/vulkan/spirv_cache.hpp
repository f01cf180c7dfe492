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
// USAGE
//     aogen::vulkan::spirv_cache cache;
//     cache.compile_all(sources);                          // every distinct text, on all cores
//     const std::vector<uint32_t>& words = cache.get(source);   // compiled here on a miss
//
// ERRORS
//   aogen::error from compile(), naming the shader (compile_all: the first failure, after
//   every thread has finished).
#pragma once

#include "../codegen.hpp"
#include "../compile.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
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
    const std::vector<uint32_t>& get(const codegen::shader_source& s)
    {
        const key k{s.stage, s.glsl};
        {
            std::lock_guard<std::mutex> lock(mutex_);
            auto it = words_.find(k);
            if (it != words_.end()) return it->second;
        }
        std::vector<uint32_t> words = compile::compile(s.glsl, s.stage, s.name, {compile::target::spv}).spirv;
        std::lock_guard<std::mutex> lock(mutex_);
        return words_.emplace(k, std::move(words)).first->second; // a concurrent twin's insert wins; both are equal
    }

    // Makes `words` the SPIR-V of `s`: for sources whose text is not GLSL (the HLSL round trip
    // compiles HLSL with compile::hlsl_to_spirv and runs it under the variant's own passes).
    void put(const codegen::shader_source& s, std::vector<uint32_t> words)
    {
        std::lock_guard<std::mutex> lock(mutex_);
        words_[key{s.stage, s.glsl}] = std::move(words);
    }

    // Compiles every source not yet in the cache, on up to `threads` threads.
    void compile_all(const std::vector<codegen::shader_source>& sources, unsigned threads = std::thread::hardware_concurrency())
    {
        std::atomic<size_t> next{0};
        std::exception_ptr failure;
        std::mutex failure_mutex;
        const auto work = [&] {
            for (size_t i = next++; i < sources.size(); i = next++) {
                try {
                    get(sources[i]);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(failure_mutex);
                    if (!failure) failure = std::current_exception();
                }
            }
        };
        std::vector<std::thread> pool;
        for (unsigned t = 1; t < std::max(1u, threads); ++t) pool.emplace_back(work);
        work();
        for (std::thread& t : pool) t.join();
        if (failure) std::rethrow_exception(failure);
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
