#include "cli/args.hpp"

#include <charconv>
#include <cmath>

namespace towgeom::cli {

Args::Args(int argc, char** argv, int first, const std::vector<OptionSpec>& spec)
{
    bool optionsEnded = false;
    for (int i = first; i < argc; ++i) {
        const std::string arg = argv[i];
        if (optionsEnded || arg.size() < 2 || arg[0] != '-') {
            positional_.push_back(arg);
            continue;
        }
        if (arg == "--") {
            optionsEnded = true;
            continue;
        }
        std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
        std::optional<std::string> inlineValue;
        if (const auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (name == "h") name = "help";
        const OptionSpec* found = nullptr;
        for (const OptionSpec& s : spec)
            if (s.name == name) found = &s;
        if (!found) throw UsageError("unknown option '" + arg + "'");
        if (!found->takesValue) {
            if (inlineValue) throw UsageError("option --" + name + " takes no value");
            values_[name].push_back("");
            continue;
        }
        if (!inlineValue) {
            if (i + 1 >= argc) throw UsageError("option --" + name + " needs a value");
            inlineValue = argv[++i];
        }
        values_[name].push_back(*inlineValue);
    }
}

std::optional<std::string> Args::value(const std::string& name) const
{
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    if (it->second.size() > 1) throw UsageError("option --" + name + " given more than once");
    return it->second.front();
}

std::optional<double> Args::number(const std::string& name) const
{
    const auto text = value(name);
    if (!text) return std::nullopt;
    double x = 0.0;
    const auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), x);
    if (ec != std::errc() || end != text->data() + text->size() || !std::isfinite(x))
        throw UsageError("option --" + name + " needs a number, got '" + *text + "'");
    return x;
}

double Args::positive(const std::string& name) const
{
    const auto x = number(name);
    if (!x) return 0.0;
    if (!(*x > 0.0)) throw UsageError("--" + name + " must be a positive number");
    return *x;
}

std::size_t Args::threads() const
{
    const auto n = number("threads");
    if (!n) return 0;
    if (!(*n >= 1.0 && *n <= 1024.0) || std::floor(*n) != *n) throw UsageError("--threads must be a whole number from 1 to 1024");
    return static_cast<std::size_t>(*n);
}

std::size_t Args::maxTriangles(std::size_t fallback) const
{
    const auto n = number("max-triangles");
    if (!n) return fallback;
    if (!(*n >= 1.0 && *n <= 1e15) || std::floor(*n) != *n) throw UsageError("--max-triangles must be a whole number from 1 to 1e15");
    return static_cast<std::size_t>(*n);
}

}  // namespace towgeom::cli
