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
    for (std::size_t k = 0; k < entries_.size(); ++k) {
        std::error_code ec;
        std::filesystem::rename(entries_[k].temporary, entries_[k].path, ec);
        if (ec) {
            // Take back what is already in place, so no partial set of outputs remains.
            for (std::size_t done = 0; done < k; ++done) std::remove(entries_[done].path.c_str());
            entries_.erase(entries_.begin(), entries_.begin() + static_cast<std::ptrdiff_t>(k));
            throw Error(ErrorCode::WriteFailed, "cannot rename into place: " + ec.message(), entries_.front().path);
        }
        entries_[k].temporary.clear();
    }
    entries_.clear();
}

}  // namespace towgeom::detail
