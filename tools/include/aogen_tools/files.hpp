// aogen_tools/files.hpp — reading files, and writing them so that a failure never leaves
// half of one, or half of a set.
//
// Shared by the tools that write files: the `aogen` command line (generator/) and the
// report (report).
//
// READING
//   read_file(path): the bytes of a regular file (or a stream: a FIFO, /dev/stdin).
//   A directory, a missing or unreadable file is an aogen::error naming the path.
//
// WRITING ONE FILE: write_file(path, bytes) — what the destination is decides how:
//   a regular file, or nothing yet   written to a temporary name beside it and renamed
//                                    over it once complete; left untouched when it
//                                    already holds exactly these bytes (a build that
//                                    depends on it does not redo work)
//   a symbolic link                  resolved: the file it points to is written as above,
//                                    the link stays a link (it is never replaced by a
//                                    file); a link to nothing is refused
//   a FIFO, a terminal, /dev/stdout  written as a stream, in place; a FIFO no process
//   or any other non-regular file    reads from is refused at once instead of waiting
//   a directory, an empty path       refused
// emit(path, bytes) is write_file, or standard output for an empty path or "-".
//
// WRITING A SET: file_set — add() every file of a generation first, then commit():
//   1. every destination is checked (a directory or a link where a file belongs, a file
//      where a folder belongs, a folder that cannot be written: refused before anything is
//      written; a link inside a generation is refused, not replaced);
//   2. every file whose bytes change is written into a staging folder beside the
//      destination folder (".<name>.aogen-staging-<pid>", on the same file system);
//   3. each staged file is renamed over its destination, the old file first moved into
//      the staging folder; if a rename fails, the ones done are undone and the old files
//      put back;
//   4. the staging folder is removed.
//   So a failing generation leaves the destination folder as it was — including one that
//   never existed, which is not left behind.
#pragma once

#include <aogen/error.hpp>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace aogen::tools {

namespace fs = std::filesystem;

namespace detail {

inline std::string shown(const fs::path& p) { return printable(p.string()); }

// The type of what `p` names, following symbolic links; not_found when there is nothing.
inline fs::file_type target_type(const fs::path& p)
{
    std::error_code ec;
    const fs::file_status st = fs::status(p, ec);
    return ec ? fs::file_type::not_found : st.type();
}

inline bool file_holds(const fs::path& path, std::string_view bytes)
{
    if (target_type(path) != fs::file_type::regular) return false; // never read a stream to compare
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::string existing((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return existing == bytes;
}

// Writes `bytes` to an existing stream (FIFO, terminal, /dev/stdout): no temporary file,
// no rename. A FIFO without a reader is refused instead of blocking for ever.
inline void write_stream(const fs::path& path, std::string_view bytes)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int e = errno;
        if (e == ENXIO) fail(shown(path), "is a FIFO that no process is reading", "valid: a regular file, or a FIFO with a reader");
        fail(shown(path), std::string("cannot be opened for writing: ") + std::strerror(e), "valid: a writable path");
    }
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK); // a reader is there: blocking writes from here on
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int e = errno;
            ::close(fd);
            fail(shown(path), std::string("cannot be written: ") + std::strerror(e), "valid: a writable path");
        }
        done += size_t(n);
    }
    ::close(fd);
}

// `bytes` to a temporary file beside `path`, renamed over it.
inline void replace_atomically(const fs::path& path, std::string_view bytes)
{
    std::error_code ec;
    const fs::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) {
            fs::remove(temporary, ec);
            fail(shown(path), "cannot be written", "valid: a writable path");
        }
    }
    fs::rename(temporary, path, ec);
    if (ec) {
        fs::remove(temporary, ec);
        fail(shown(path), "cannot be written: " + ec.message(), "valid: a writable path");
    }
}

// The first existing ancestor of `p` (p itself if it exists).
inline fs::path existing_ancestor(fs::path p)
{
    std::error_code ec;
    while (!p.empty() && !fs::exists(fs::symlink_status(p, ec))) {
        const fs::path parent = p.parent_path();
        if (parent == p) break;
        p = parent;
    }
    return p.empty() ? fs::path(".") : p;
}

} // namespace detail

// aogen::error unless `dir` is, or can be made, a folder we may write into: every part
// of it that exists is a folder (through links), and the deepest existing one is writable.
// Nothing is created. What a tool checks before any expensive work.
inline void require_writable_folder(const fs::path& dir, std::string_view what = "output directory")
{
    if (dir.empty()) fail(what, "is empty", "valid: a directory path");
    const fs::path base = detail::existing_ancestor(dir);
    const fs::file_type t = detail::target_type(base);
    if (t != fs::file_type::directory)
        fail(detail::shown(dir), base == dir ? "is not a directory" : detail::shown(base) + " in it is not a directory", std::string("valid: a directory for the ") + std::string(what));
    if (::access(base.c_str(), W_OK | X_OK) != 0)
        fail(detail::shown(dir), detail::shown(base) + " cannot be written: " + std::strerror(errno), "valid: a writable directory");
}

// Writes one file (see WRITING ONE FILE above). Returns false when a regular file
// already held exactly these bytes and was left alone.
inline bool write_file(const fs::path& path, std::string_view bytes)
{
    if (path.empty()) fail("output file", "is empty", "valid: a file path, or - for standard output");
    std::error_code ec;
    const bool link = fs::is_symlink(fs::symlink_status(path, ec));
    fs::path target = path;
    switch (detail::target_type(path)) { // through any links
    case fs::file_type::directory: fail(detail::shown(path), "is a directory", "valid: a file path");
    case fs::file_type::not_found:
        if (link) fail(detail::shown(path), "is a symbolic link to nothing", "valid: a link to a file, or a file");
        break;
    case fs::file_type::regular:
        if (link) target = fs::canonical(path); // the file the links lead to is replaced, the links stay
        break;
    default: detail::write_stream(path, bytes); return true; // FIFO, character device, socket: a stream
    }
    if (detail::file_holds(target, bytes)) return false;
    require_writable_folder(target.has_parent_path() ? target.parent_path() : fs::path("."), "file");
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    if (ec) fail(detail::shown(target.parent_path()), "cannot be created: " + ec.message(), "valid: a writable path");
    detail::replace_atomically(target, bytes);
    return true;
}

// A closed pipe on standard output becomes a write error (EPIPE) that finish_standard_output
// reports, instead of SIGPIPE ending the program without a word.
inline void keep_broken_pipes_as_errors() { ::signal(SIGPIPE, SIG_IGN); }

// aogen::error unless everything written to standard output reached it (a full disk, a
// closed or broken pipe): a command that prints must not exit 0 having printed nothing.
inline void finish_standard_output()
{
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0)
        fail("standard output", std::string("cannot be written: ") + (errno ? std::strerror(errno) : "the stream failed"),
             "valid: a standard output that can be written, or --out FILE");
}

// Writes to `path`, or to standard output when `path` is empty or "-".
inline void emit(const std::string& path, std::string_view bytes)
{
    if (path.empty() || path == "-") {
        std::cout.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        std::cout.flush();
        return;
    }
    write_file(path, bytes);
}

inline std::string read_file(const std::string& path)
{
    const fs::file_type t = detail::target_type(path);
    if (t == fs::file_type::not_found) fail(detail::shown(path), "does not exist", "valid: an existing, readable file");
    if (t == fs::file_type::directory) fail(detail::shown(path), "is a directory", "valid: a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(detail::shown(path), std::string("cannot be read: ") + std::strerror(errno), "valid: an existing, readable file");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) fail(detail::shown(path), "cannot be read", "valid: an existing, readable file");
    return text;
}

// A set of files under one folder, written all or nothing (see WRITING A SET above).
class file_set {
public:
    explicit file_set(fs::path folder) : folder_(std::move(folder)) {}

    // `relative` under the folder ("a/b.spv"), replacing an earlier add of the same path.
    void add(const std::string& relative, std::string bytes) { files_[relative] = std::move(bytes); }
    const std::map<std::string, std::string>& files() const { return files_; }

    // Writes every file whose bytes change; returns their paths (relative, sorted).
    std::vector<std::string> commit() const
    {
        const fs::path folder = resolved_folder();
        check_destinations(folder);
        std::vector<std::string> changed;
        for (const auto& [relative, bytes] : files_)
            if (!detail::file_holds(folder / relative, bytes)) changed.push_back(relative);
        if (changed.empty()) return changed;
        staging stage(folder);
        for (const std::string& relative : changed) stage.write(relative, files_.at(relative));
        stage.move_into_place(changed);
        return changed;
    }

private:
    // The folder with a link at its end resolved (a link is written through, never replaced).
    fs::path resolved_folder() const
    {
        require_writable_folder(folder_);
        std::error_code ec;
        if (fs::is_symlink(fs::symlink_status(folder_, ec))) return fs::canonical(folder_);
        return folder_;
    }

    // Every destination a regular file or nothing (links to files allowed), every folder
    // on its way a folder or nothing.
    void check_destinations(const fs::path& folder) const
    {
        for (const auto& [relative, bytes] : files_) {
            const fs::path dest = folder / relative;
            for (fs::path p = dest.parent_path(); p != folder && !p.empty(); p = p.parent_path()) {
                const fs::file_type t = detail::target_type(p);
                if (t != fs::file_type::not_found && t != fs::file_type::directory)
                    fail(detail::shown(p), "is not a directory, and " + detail::shown(relative) + " is to be written in it", "valid: a directory or nothing there");
            }
            std::error_code ec;
            if (fs::is_symlink(fs::symlink_status(dest, ec)))
                fail(detail::shown(dest), "is a symbolic link, which writing the set would replace", "valid: a regular file or nothing there");
            const fs::file_type t = detail::target_type(dest);
            if (t != fs::file_type::not_found && t != fs::file_type::regular)
                fail(detail::shown(dest), "is not a regular file, and would be replaced", "valid: a regular file or nothing there");
        }
    }

    // The staging folder beside the destination folder, removed with whatever is left in it.
    class staging {
    public:
        explicit staging(const fs::path& folder) : folder_(folder)
        {
            const fs::path parent = folder.has_parent_path() ? folder.parent_path() : fs::path(".");
            root_ = parent / ("." + folder.filename().string() + ".aogen-staging-" + std::to_string(::getpid()));
            std::error_code ec;
            fs::remove_all(root_, ec);
            fs::create_directories(root_ / "new", ec);
            if (!ec) fs::create_directories(root_ / "old", ec);
            // Named by the folder the user gave: the staging folder is ours, not theirs.
            if (ec)
                fail(detail::shown(folder), "cannot be written: no staging folder can be made beside it (" + ec.message() + ")",
                     "valid: a writable directory beside the output directory");
        }
        ~staging()
        {
            std::error_code ec;
            fs::remove_all(root_, ec);
        }

        void write(const std::string& relative, const std::string& bytes)
        {
            const fs::path p = root_ / "new" / relative;
            std::error_code ec;
            fs::create_directories(p.parent_path(), ec);
            std::ofstream out(p, std::ios::binary | std::ios::trunc);
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            out.close();
            if (ec || !out) fail(detail::shown(folder_ / relative), "cannot be written", "valid: room and permission beside the output directory");
        }

        // Renames each staged file over its destination (the old one kept in "old"), all
        // undone when one fails.
        void move_into_place(const std::vector<std::string>& changed)
        {
            std::vector<std::pair<std::string, bool>> done; // path, had an old file
            std::vector<fs::path> made_folders;
            try {
                for (const std::string& relative : changed) {
                    const fs::path dest = folder_ / relative, old = root_ / "old" / relative;
                    make_folders(dest.parent_path(), made_folders);
                    const bool existed = detail::target_type(dest) == fs::file_type::regular;
                    if (existed) move(dest, old, dest);
                    done.push_back({relative, existed});
                    move(root_ / "new" / relative, dest, dest);
                }
            } catch (...) {
                undo(done, made_folders);
                throw;
            }
        }

    private:
        // Renames `from` to `to`; a failure names `user_path`, the output file concerned.
        static void move(const fs::path& from, const fs::path& to, const fs::path& user_path)
        {
            std::error_code ec;
            fs::create_directories(to.parent_path(), ec);
            fs::rename(from, to, ec);
            if (ec) fail(detail::shown(user_path), "cannot be written: " + ec.message(), "valid: a writable output directory");
        }
        // Creates the missing folders up to `dir`, remembering them (outermost first) to undo.
        void make_folders(const fs::path& dir, std::vector<fs::path>& made) const
        {
            std::vector<fs::path> missing;
            for (fs::path p = dir; !p.empty() && !fs::exists(p); p = p.parent_path()) missing.push_back(p);
            for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
                std::error_code ec;
                fs::create_directory(*it, ec);
                if (ec) fail(detail::shown(*it), "cannot be created: " + ec.message(), "valid: a writable output directory");
                made.push_back(*it);
            }
        }
        void undo(const std::vector<std::pair<std::string, bool>>& done, const std::vector<fs::path>& made) const
        {
            std::error_code ec;
            for (auto it = done.rbegin(); it != done.rend(); ++it) {
                const fs::path dest = folder_ / it->first;
                fs::remove(dest, ec);
                if (it->second) fs::rename(root_ / "old" / it->first, dest, ec);
            }
            for (auto it = made.rbegin(); it != made.rend(); ++it) fs::remove(*it, ec); // only if empty again
        }

        fs::path folder_, root_;
    };

    fs::path folder_;
    std::map<std::string, std::string> files_;
};

} // namespace aogen::tools
