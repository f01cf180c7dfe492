// tests/fuzz/fuzz_support.hpp — what every fuzz target of the JSON readers shares: which
// outcomes of a parse are answers and which are findings.
//
// WHAT
//   text_of(data, size)        libFuzzer's bytes as the std::string the readers take.
//   expect_errors(work)        runs `work`; an aogen::error it throws is the expected answer
//                              to bad input, and so (by default) is any other std::exception.
//
// WHY these outcomes
//   Every reader rejects bad input by throwing aogen::error, whose message names the file, the
//   field, the value and what is valid (aogen/error.hpp). The programs also print any other
//   std::exception as one line and exit non-zero (generator/main.cpp, report/main.cpp),
//   so an nlohmann::json::type_error escaping a reader is a poor message, not a failure.
//   Everything else is a finding, and libFuzzer saves the input that caused it: a crash or a
//   sanitizer report (ASan, UBSan: built with -fno-sanitize-recover, so the first report
//   aborts), an exception of a type that is no std::exception (it leaves
//   LLVMFuzzerTestOneInput, and std::terminate aborts), a hang (-timeout) and running out of
//   memory (-rss_limit_mb, -malloc_limit_mb).
//
//   AOGEN_FUZZ_STRICT=1 in the environment narrows the expected answers to aogen::error: any
//   other std::exception then aborts, naming its type, so that a run collects the inputs whose
//   messages do not say which field was wrong.
//
// Every target also links nesting_mutator.cpp, a mutation that nests values deeper.
#pragma once

#include <aogen/error.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <typeinfo>

namespace aogen::fuzz {

inline std::string text_of(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

inline bool strict()
{
    static const bool on = [] {
        const char* v = std::getenv("AOGEN_FUZZ_STRICT");
        return v != nullptr && std::strcmp(v, "1") == 0;
    }();
    return on;
}

// Runs `work`, taking the errors a reader may answer with; anything else propagates, or
// has already aborted.
template <class Work>
void expect_errors(Work&& work)
{
    try {
        work();
    } catch (const aogen::error&) {
        // The answer to bad input.
    } catch (const std::exception& e) {
        if (strict()) {
            std::fprintf(stderr, "aogen fuzz: a %s escaped, not an aogen::error: %s\n", typeid(e).name(), e.what());
            std::abort();
        }
    }
}

} // namespace aogen::fuzz
