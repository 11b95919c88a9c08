// All-or-nothing output: files are written under temporary names and renamed into place only
// when every one of them has been written, so an error never leaves half-written output; a
// failed run leaves the output directory exactly as it was, older files included.
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class OutputFiles {
public:
    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    /// Unless commit() succeeded: removes every temporary file, then the directories
    /// makeDirectory() created (those left empty).
    ~OutputFiles();

    /// Creates @p directory and its missing parents; the ones created are removed again when
    /// the output is not committed.
    /// @throws towgeom::Error (WriteFailed) naming @p directory when it cannot be made.
    void makeDirectory(const std::string& directory);
    /// Opens a temporary file that commit() will rename to @p path.
    /// @throws towgeom::Error (WriteFailed) naming @p path.
    std::ostream& open(const std::string& path);
    /// Flushes every file and renames it into place. A file it replaces is kept first under a
    /// backup name in the same directory (a hard link, or a rename where links are not
    /// supported); the backups are removed once every file is in place.
    /// @throws towgeom::Error (WriteFailed) naming the file; every file already renamed by this
    ///         call is taken back (the file it replaced restored from its backup, or removed when
    ///         there was none), and no temporary or backup file remains.
    void commit();

private:
    struct Entry {
        std::string path;
        std::string temporary;
        std::string backup;     // the file path replaced, kept until commit() succeeds; empty: none
        bool backupIsLink = false;  // backup is a second link to path (path still in place)
        std::unique_ptr<std::ofstream> stream;
    };
    /// Undoes the renames of entries_[0, failed) and the backup of entries_[failed]; returns
    /// a note on anything that could not be restored (empty when all was).
    std::string rollBack(std::size_t failed);

    std::vector<Entry> entries_;
    std::vector<std::string> createdDirectories_;  // outermost first
    bool committed_ = false;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
