// Runs the towgeom executable from the tests and reads what it printed.
#pragma once

#include <catch2/catch.hpp>

#include <towgeom/point.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace towgeom::testing {

struct Run {
    int status = -1;
    std::string out, err;
};

/// How often @p what occurs in @p text (overlapping occurrences counted).
inline std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// The point a message names as "near (x, y, z)" (an error's or a warning's place).
inline Point3 placeNamedIn(const std::string& message)
{
    const std::size_t open = message.find("near ("), close = message.find(')', open);
    REQUIRE(close != std::string::npos);
    std::istringstream place(message.substr(open + 6, close - open - 6));
    Point3 at;
    char comma = 0;
    place >> at.x >> comma >> at.y >> comma >> at.z;
    REQUIRE(place);
    return at;
}

inline std::string slurp(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Runs the towgeom executable with @p args (a shell-quoted string).
inline Run cli(const std::string& args)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("towgeom_cli_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string command =
        std::string("'") + TOWGEOM_CLI + "' " + args + " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() + "'";
    const int raw = std::system(command.c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(dir / "out");
    r.err = slurp(dir / "err");
    return r;
}

/// Runs a shell command, capturing its stdout (redirect stderr in @p command if wanted).
inline Run runShell(const std::string& command)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("towgeom_sh_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const int raw = std::system((command + " >'" + (dir / "out").string() + "'").c_str());
    Run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(dir / "out");
    return r;
}

/// Every entry under @p dir, recursively, by relative path: a file's bytes, "<dir>" for a
/// directory, "<link>" + target for a symbolic link. Two snapshots compare equal when nothing
/// under @p dir was added, removed or changed.
inline std::map<std::string, std::string> snapshot(const std::filesystem::path& dir)
{
    std::map<std::string, std::string> entries;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        const std::string name = e.path().lexically_relative(dir).string();
        if (e.is_symlink())
            entries[name] = "<link>" + std::filesystem::read_symlink(e.path()).string();
        else if (e.is_directory())
            entries[name] = "<dir>";
        else
            entries[name] = slurp(e.path());
    }
    return entries;
}

/// The names in a snapshot, for messages.
inline std::string names(const std::map<std::string, std::string>& entries)
{
    std::string s;
    for (const auto& [name, content] : entries) s += name + " ";
    return s;
}

inline double jsonNumber(const std::string& json, const std::string& key, std::size_t nth = 0)
{
    const std::regex re("\"" + key + "\":(-?[0-9.eE+-]+)");
    auto it = std::sregex_iterator(json.begin(), json.end(), re);
    for (std::size_t k = 0; k < nth && it != std::sregex_iterator(); ++k) ++it;
    REQUIRE(it != std::sregex_iterator());
    return std::stod((*it)[1].str());
}

}  // namespace towgeom::testing
