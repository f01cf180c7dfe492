// tests/fuzz/nesting_mutator.cpp — libFuzzer's own mutations, plus one it lacks: nesting a
// JSON value deeper. Linked into every fuzz target (LLVMFuzzerCustomMutator).
//
// WHY
//   A reader that recurses once per level of nesting (nlohmann::json::dump() does, and error
//   messages quote values with it) runs out of stack on a deep enough document. libFuzzer
//   will not write one: it changes a few bytes at a time and keeps an input only when it
//   reaches code, or a hit count of it, that no input reached before. Past a few levels each
//   level runs the code the one before ran, so nothing leads it deeper; and every '[' it
//   adds needs its ']', or the text is no JSON and the reader stops at the parse.
//
// HOW
//   One mutation in eight takes one value of the input (a number, string, literal, array or
//   object, found from a random byte that starts one) and wraps it in 2^k arrays, k random
//   and the result within max_size: {"count": 4} becomes {"count": [[[[4]]]]}. The number of
//   levels is log-uniform, so shallow and deep wrappings are tried as often. The other seven
//   are libFuzzer's (LLVMFuzzerMutate, which also uses the -dict tokens).
//   scripts/fuzz.sh runs the targets on a 1 MiB stack and -max_len=32768: a few thousand
//   levels then show what would need some 50 000 on the main thread's 8 MiB.
//
//   AOGEN_FUZZ_MAX_NESTING=N in the environment keeps what this mutation writes within N
//   levels of nesting (counting those the input had). While a stack overflow that depth finds
//   is known and not yet fixed, it would end every run within seconds; a cap well below it
//   (1000 on the 1 MiB stack, where ~7000 overflow) lets a run look for the other faults.
//   libFuzzer's own mutations may still join two deep inputs into a deeper one, but not the
//   sevenfold that takes.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

bool in_literal(uint8_t c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '-' || c == '+' || c == '.';
}

// The index of the '"' that closes the string opened at data[i]; size when none does.
size_t string_end(const uint8_t* data, size_t size, size_t i)
{
    for (size_t j = i + 1; j < size; ++j) {
        if (data[j] == '\\') ++j;
        else if (data[j] == '"') return j;
    }
    return size;
}

bool opens(uint8_t c) { return c == '[' || c == '{'; }
bool closes(uint8_t c) { return c == ']' || c == '}'; }

// The end (one past) of the value that starts at data[i], or 0 when none starts there.
// A lexical guess, not a parse: a '[' inside a string is taken for an array, and a wrong
// guess is one more mutation that the reader rejects.
size_t value_end(const uint8_t* data, size_t size, size_t i)
{
    if (data[i] == '"') {
        const size_t close = string_end(data, size, i);
        return close < size ? close + 1 : 0;
    }
    if (opens(data[i])) {
        size_t depth = 0;
        for (size_t j = i; j < size; ++j) {
            if (data[j] == '"') j = string_end(data, size, j);
            else if (opens(data[j])) ++depth;
            else if (closes(data[j]) && --depth == 0) return j + 1;
        }
        return 0;
    }
    if (in_literal(data[i]) && (i == 0 || !in_literal(data[i - 1]))) { // a literal's first byte
        size_t j = i;
        while (j < size && in_literal(data[j])) ++j;
        return j;
    }
    return 0;
}

// The deepest nesting of brackets in data[0, size), closed or not, strings skipped.
size_t nesting_depth(const uint8_t* data, size_t size)
{
    size_t depth = 0, deepest = 0;
    for (size_t j = 0; j < size; ++j) {
        if (data[j] == '"') j = string_end(data, size, j);
        else if (opens(data[j])) deepest = std::max(deepest, ++depth);
        else if (closes(data[j]) && depth > 0) --depth;
    }
    return deepest;
}

size_t max_levels()
{
    static const size_t cap = [] {
        const char* v = std::getenv("AOGEN_FUZZ_MAX_NESTING");
        return v != nullptr && *v != '\0' ? size_t(std::strtoull(v, nullptr, 10)) : std::numeric_limits<size_t>::max();
    }();
    return cap;
}

// Wraps one value of data[0, size) in arrays; the new size, or 0 when no value was found
// or there is no room.
size_t nest_deeper(uint8_t* data, size_t size, size_t max_size, std::minstd_rand& random)
{
    if (size == 0 || max_size < size + 2) return 0;
    size_t begin = 0, end = 0;
    for (int attempt = 0; attempt < 16 && end == 0; ++attempt) {
        begin = std::uniform_int_distribution<size_t>(0, size - 1)(random);
        end = value_end(data, size, begin);
    }
    if (end == 0) return 0;
    size_t room = (max_size - size) / 2;
    if (max_levels() != std::numeric_limits<size_t>::max()) {
        const size_t depth = nesting_depth(data, size);
        room = std::min(room, max_levels() > depth ? max_levels() - depth : 0);
    }
    if (room == 0) return 0;
    int max_log2 = 0;
    while ((size_t(2) << max_log2) <= room) ++max_log2;
    const size_t levels = std::min(room, size_t(1) << std::uniform_int_distribution<int>(0, max_log2)(random));

    std::vector<uint8_t> out;
    out.reserve(size + 2 * levels);
    out.insert(out.end(), data, data + begin);
    out.insert(out.end(), levels, '[');
    out.insert(out.end(), data + begin, data + end);
    out.insert(out.end(), levels, ']');
    out.insert(out.end(), data + end, data + size);
    std::memcpy(data, out.data(), out.size());
    return out.size();
}

} // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed)
{
    std::minstd_rand random(seed);
    if (random() % 8 == 0)
        if (const size_t nested = nest_deeper(data, size, max_size, random)) return nested;
    return LLVMFuzzerMutate(data, size, max_size);
}
