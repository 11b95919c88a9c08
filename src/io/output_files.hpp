// All-or-nothing output: files are written under temporary names and renamed into place only
// when every one of them has been written, so an error never leaves half-written output.
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace towgeom::detail {

class OutputFiles {
public:
    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    /// Removes every temporary file not yet committed.
    ~OutputFiles();

    /// Opens a temporary file that commit() will rename to @p path.
    /// @throws towgeom::Error (WriteFailed) naming @p path.
    std::ostream& open(const std::string& path);
    /// Flushes and renames every file into place.
    /// @throws towgeom::Error (WriteFailed) naming the file; files already renamed by this call
    ///         are removed again (a file they replaced is lost), the temporaries too.
    void commit();

private:
    struct Entry {
        std::string path;
        std::string temporary;
        std::unique_ptr<std::ofstream> stream;
    };
    std::vector<Entry> entries_;
};

}  // namespace towgeom::detail
