#include "cli/args.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iterator>

#include <CLI/CLI.hpp>

namespace towgeom::cli {

Args::Args(int argc, char** argv, int first, const std::vector<OptionSpec>& spec)
{
    // CLI11 does the parsing, the same for every subcommand: unknown options, missing values and
    // repeated values are its rules. A value option takes exactly one value per occurrence (all
    // occurrences kept: value() refuses a repeat, values() takes them). Arguments after `--` and
    // the arguments CLI11 leaves (none starting with '-') are the inputs, taken verbatim.
    CLI::App app;
    app.set_help_flag();  // -h/--help is one of the spec's flags: each command prints its own help
    app.allow_extras(true);
    std::map<std::string, bool> flags;
    for (const OptionSpec& s : spec) {
        const std::string names = s.name == "help" ? "-h,--help" : "--" + s.name;
        if (s.takesValue)
            app.add_option(names, values_[s.name])
                ->expected(1)
                ->allow_extra_args(false)
                ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
        else
            app.add_flag(names, flags[s.name]);
    }
    int end = first;
    while (end < argc && std::string(argv[end]) != "--") ++end;
    std::vector<const char*> args{"towgeom"};
    for (int i = first; i < end; ++i) {
        const std::string arg = argv[i];
        // A flag takes no value, not even an empty one or "true".
        const auto eq = arg.find('=');
        if (arg.rfind("--", 0) == 0 && eq != std::string::npos && flags.count(arg.substr(2, eq - 2)))
            throw UsageError("option " + arg.substr(0, eq) + " takes no value");
        args.push_back(argv[i]);
    }
    try {
        app.parse(static_cast<int>(args.size()), args.data());
    } catch (const CLI::ParseError& e) {
        throw UsageError(e.what());
    }
    for (const std::string& r : app.remaining()) {
        if (r.size() >= 2 && r[0] == '-') throw UsageError("The following argument was not expected: " + r);
        positional_.push_back(r);
    }
    for (int i = end + 1; i < argc; ++i) positional_.push_back(argv[i]);
    for (auto it = values_.begin(); it != values_.end();) it = it->second.empty() ? values_.erase(it) : std::next(it);
    for (const auto& [name, given] : flags)
        if (given) values_[name].push_back("");
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

std::size_t Args::whole(const std::string& name, std::size_t fallback, double lo, double hi, const char* range) const
{
    const auto n = number(name);
    if (!n) return fallback;
    if (!(*n >= lo && *n <= hi) || std::floor(*n) != *n) throw UsageError("--" + name + " must be a whole number from " + range);
    return static_cast<std::size_t>(*n);
}

std::size_t Args::threads() const { return whole("threads", 0, 1.0, 1024.0, "1 to 1024"); }

std::size_t Args::maxTriangles(std::size_t fallback) const { return whole("max-triangles", fallback, 1.0, 1e15, "1 to 1e15"); }

std::vector<double> numberList(const std::string& text)
{
    std::vector<double> v;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t comma = std::min(text.find(',', at), text.size());
        const std::string part = text.substr(at, comma - at);
        char* end = nullptr;
        const double x = std::strtod(part.c_str(), &end);
        if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(x)) return {};
        v.push_back(x);
        at = comma + 1;
    }
    return v;
}

}  // namespace towgeom::cli
