// The benchmarks' textile: a 2/2 twill with 0.08 overlap (every crossing interpenetrates),
// 8 warps x 8 wefts of 400 sections x 64 points unless --tows, --sections, --points say
// otherwise; every other "--name value" or "--flag" is kept for the benchmark itself.
#pragma once

#include <towgeom/weave.hpp>

#include <map>
#include <string>

namespace towgeom::bench {

struct TwillArgs {
    WeaveOptions weave;
    std::map<std::string, std::string> other;  ///< "--name" -> value ("" for a flag)
    /// The value of @p name as a number, or @p fallback.
    double number(const std::string& name, double fallback) const
    {
        const auto it = other.find(name);
        return it == other.end() ? fallback : std::stod(it->second);
    }
    bool flag(const std::string& name) const { return other.count(name) != 0; }
};

inline TwillArgs parseTwillArgs(int argc, char** argv)
{
    TwillArgs a;
    a.weave.kind = WeaveKind::Twill;
    a.weave.overlap = 0.08;
    a.weave.warps = a.weave.wefts = 8;
    a.weave.sectionsPerYarn = 400;
    a.weave.pointsPerSection = 64;
    for (int i = 1; i < argc; ++i) {
        const std::string name = argv[i];
        const bool valued = i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0;
        const std::string value = valued ? argv[++i] : "";
        if (name == "--tows") a.weave.warps = a.weave.wefts = std::stoul(value);
        else if (name == "--sections") a.weave.sectionsPerYarn = std::stoul(value);
        else if (name == "--points") a.weave.pointsPerSection = std::stoul(value);
        else a.other[name] = value;
    }
    return a;
}

}  // namespace towgeom::bench
