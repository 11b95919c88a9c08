// The towgeom subcommands' command lines, parsed by CLI11: --name VALUE, --name=VALUE, flags,
// repeatable options and positional arguments, with the same errors for every subcommand.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace towgeom::cli {

/// A mistake in how the command was called (exit 2 with a hint to --help).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct OptionSpec {
    std::string name;  // without the leading dashes
    bool takesValue = false;
};

/// The finite numbers of a comma-separated list (each as strtod reads it, whole); empty if any
/// part is not one.
std::vector<double> numberList(const std::string& text);

class Args {
public:
    /// Parses argv[first..argc) with CLI11; throws UsageError (CLI11's message) for unknown
    /// options, missing values or a value given to a flag. The spec's "help" is -h and --help.
    Args(int argc, char** argv, int first, const std::vector<OptionSpec>& spec);

    bool has(const std::string& name) const { return values_.count(name) != 0; }
    std::optional<std::string> value(const std::string& name) const;
    /// Every value given for a repeatable option, in order.
    std::vector<std::string> values(const std::string& name) const
    {
        const auto it = values_.find(name);
        return it == values_.end() ? std::vector<std::string>{} : it->second;
    }
    const std::vector<std::string>& positional() const { return positional_; }
    /// The value of @p name as a number; throws UsageError if it is not one.
    std::optional<double> number(const std::string& name) const;
    /// The value of @p name as a positive finite number, 0 when absent (meaning "default").
    double positive(const std::string& name) const;
    /// The value of @p name as a whole number from @p lo to @p hi (@p range says so in the
    /// error), @p fallback when absent.
    std::size_t whole(const std::string& name, std::size_t fallback, double lo, double hi, const char* range) const;
    /// --threads N as a whole number from 1 to 1024, 0 when absent (all hardware threads).
    std::size_t threads() const;
    /// --max-triangles N as a whole number from 1 to 1e15; @p fallback when absent.
    std::size_t maxTriangles(std::size_t fallback) const;

private:
    std::map<std::string, std::vector<std::string>> values_;
    std::vector<std::string> positional_;
};

}  // namespace towgeom::cli
