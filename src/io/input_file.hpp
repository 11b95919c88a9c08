// An input file opened for reading, or a typed error naming it.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// @p path opened in binary mode; @p what names the expected content in the message for a
/// directory ("a stack file").
/// @throws Error (FileNotFound) if it does not exist, (FileUnreadable) if it is a directory or
/// cannot be opened.
inline std::ifstream openInputFile(const std::string& path, const std::string& what)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw Error(ErrorCode::FileNotFound, "no such file", path);
    if (fs::is_directory(status)) throw Error(ErrorCode::FileUnreadable, "is a directory, not " + what, path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(ErrorCode::FileUnreadable, "cannot open for reading", path);
    return in;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
