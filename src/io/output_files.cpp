#include "io/output_files.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace fs = std::filesystem;

namespace {

/// A name in the directory of @p path no other call of this process has used.
std::string uniqueName(const std::string& path, const char* kind)
{
    static std::atomic<unsigned> counter{0};
    return path + kind + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

}  // namespace

OutputFiles::~OutputFiles()
{
    for (Entry& e : entries_) {
        e.stream.reset();
        if (!e.temporary.empty()) std::remove(e.temporary.c_str());
    }
    if (committed_) return;
    // Innermost first; a directory someone else has put files into meanwhile stays.
    for (auto it = createdDirectories_.rbegin(); it != createdDirectories_.rend(); ++it) {
        std::error_code ec;
        fs::remove(*it, ec);
    }
}

void OutputFiles::makeDirectory(const std::string& directory)
{
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = fs::path(directory).lexically_normal(); !p.empty(); p = p.parent_path()) {
        if (fs::exists(fs::symlink_status(p, ec))) break;
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (it->filename().empty()) continue;  // a trailing separator
        if (!fs::create_directory(*it, ec) || ec) break;
        createdDirectories_.push_back(it->string());
    }
    if (!fs::is_directory(directory, ec)) throw Error(ErrorCode::WriteFailed, "cannot create output directory", directory);
}

std::ostream& OutputFiles::open(const std::string& path)
{
    Entry e;
    e.path = path;
    e.temporary = uniqueName(path, ".tmp.");
    e.stream = std::make_unique<std::ofstream>(e.temporary, std::ios::binary | std::ios::trunc);
    if (!*e.stream) throw Error(ErrorCode::WriteFailed, "cannot open for writing", path);
    entries_.push_back(std::move(e));
    return *entries_.back().stream;
}

std::string OutputFiles::rollBack(std::size_t failed)
{
    std::string trouble;
    // Newest first, so that a path given twice ends with its oldest content.
    for (std::size_t k = failed + 1; k-- > 0;) {
        Entry& e = entries_[k];
        const bool renamed = k < failed;
        if (e.backup.empty()) {
            if (renamed && std::remove(e.path.c_str()) != 0 && errno != ENOENT)
                trouble += "; could not remove " + e.path;
            continue;
        }
        if (!renamed && e.backupIsLink) {
            // The file was never replaced: its second name goes.
            std::remove(e.backup.c_str());
        } else if (std::rename(e.backup.c_str(), e.path.c_str()) != 0) {
            trouble += "; could not restore " + e.path + " (its old content is in " + e.backup + ")";
            continue;
        }
        e.backup.clear();
    }
    return trouble;
}

void OutputFiles::commit()
{
    for (Entry& e : entries_) {
        e.stream->flush();
        if (!*e.stream) throw Error(ErrorCode::WriteFailed, "write failed (disk full?)", e.path);
        e.stream->close();
        if (e.stream->fail()) throw Error(ErrorCode::WriteFailed, "write failed on close", e.path);
    }
    for (std::size_t k = 0; k < entries_.size(); ++k) {
        Entry& e = entries_[k];
        std::string failure;
        // Keep what the rename would replace. A directory is never replaced (the rename fails).
        std::error_code ec;
        const fs::file_status old = fs::symlink_status(e.path, ec);
        if (fs::exists(old) && !fs::is_directory(old)) {
            std::string backup = uniqueName(e.path, ".bak.");
            int rc = ::link(e.path.c_str(), backup.c_str());
            while (rc != 0 && errno == EEXIST) {
                backup = uniqueName(e.path, ".bak.");
                rc = ::link(e.path.c_str(), backup.c_str());
            }
            if (rc == 0) {
                e.backupIsLink = true;
            } else if (std::rename(e.path.c_str(), backup.c_str()) == 0) {  // no hard links here
                e.backupIsLink = false;
            } else {
                failure = std::string("cannot keep a backup of the existing file: ") + std::strerror(errno);
                backup.clear();
            }
            e.backup = backup;
        }
        if (failure.empty()) {
            fs::rename(e.temporary, e.path, ec);
            if (ec)
                failure = "cannot rename into place: " + ec.message();
            else
                e.temporary.clear();
        }
        if (!failure.empty()) {
            // Take back everything this call did: the directory is as it was before.
            failure += rollBack(k);
            const std::string path = e.path;
            throw Error(ErrorCode::WriteFailed, failure, path);
        }
    }
    committed_ = true;
    for (Entry& e : entries_)
        if (!e.backup.empty()) std::remove(e.backup.c_str());
    entries_.clear();
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
