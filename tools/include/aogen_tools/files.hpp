// aogen_tools/files.hpp — reading files, and writing them so that a failure never leaves half of one.
//
// Shared by the tools that write files: the `aogen` command line (generator/) and the
// report (bench/report). Every file they write goes to a temporary name beside its
// destination and is renamed over it only once complete. Unchanged files are left
// untouched, so a build that depends on them does not redo work.
#pragma once

#include <aogen/error.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace aogen::tools {

inline bool file_holds(const std::filesystem::path& path, std::string_view bytes)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::string existing((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return existing == bytes;
}

// Writes `bytes` to `path` through a temporary file and a rename. Returns false when the
// file already held exactly these bytes (and was left alone).
inline bool write_file_atomically(const std::filesystem::path& path, std::string_view bytes)
{
    if (file_holds(path, bytes)) return false;
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) fail(path.parent_path().string(), "cannot create the directory: " + ec.message(), "valid: a writable path");
    const std::filesystem::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) {
            std::filesystem::remove(temporary, ec);
            fail(path.string(), "cannot be written", "valid: a writable path");
        }
    }
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        fail(path.string(), "cannot be written: " + ec.message(), "valid: a writable path");
    }
    return true;
}

// Writes to `path`, or to standard output when `path` is empty or "-".
inline void emit(const std::string& path, std::string_view bytes)
{
    if (path.empty() || path == "-") {
        std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        std::cout.flush();
        return;
    }
    write_file_atomically(path, bytes);
}

inline std::string read_file(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot be read", "valid: an existing, readable file");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

} // namespace aogen::tools
