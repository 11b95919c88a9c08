// The CLI's own JSON (fit's and generate's reports): nlohmann-json, keys in the order written.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace towgeom::cli {

using Json = nlohmann::ordered_json;

/// @p j as compact text; an invalid UTF-8 byte in a name (names come from file names) becomes
/// U+FFFD instead of an exception.
inline std::string jsonText(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace towgeom::cli
