#include "io/output_files.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>

#include "towgeom/error.hpp"

namespace towgeom::detail {

OutputFiles::~OutputFiles()
{
    for (Entry& e : entries_) {
        e.stream.reset();
        std::remove(e.temporary.c_str());
    }
}

std::ostream& OutputFiles::open(const std::string& path)
{
    static std::atomic<unsigned> counter{0};
    Entry e;
    e.path = path;
    e.temporary = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    e.stream = std::make_unique<std::ofstream>(e.temporary, std::ios::binary | std::ios::trunc);
    if (!*e.stream) throw Error(ErrorCode::WriteFailed, "cannot open for writing", path);
    entries_.push_back(std::move(e));
    return *entries_.back().stream;
}

void OutputFiles::commit()
{
    for (Entry& e : entries_) {
        e.stream->flush();
        if (!*e.stream) throw Error(ErrorCode::WriteFailed, "write failed (disk full?)", e.path);
        e.stream->close();
        if (e.stream->fail()) throw Error(ErrorCode::WriteFailed, "write failed on close", e.path);
    }
    for (Entry& e : entries_) {
        std::error_code ec;
        std::filesystem::rename(e.temporary, e.path, ec);
        if (ec) throw Error(ErrorCode::WriteFailed, "cannot rename into place: " + ec.message(), e.path);
        e.temporary.clear();
    }
    entries_.clear();
}

}  // namespace towgeom::detail
