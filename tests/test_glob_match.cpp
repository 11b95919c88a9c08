// The --primary patterns' matcher (detail::globMatch, portable) against POSIX fnmatch() with no
// flags, which it replaces: fixed cases and random patterns over a small alphabet.
#include <catch2/catch.hpp>

#include <fnmatch.h>

#include <random>
#include <string>
#include <vector>

#include "core/glob_match.hpp"

using towgeom::detail::globMatch;

TEST_CASE("glob patterns match tow names as fnmatch does", "[glob]")
{
    CHECK(globMatch("warp_*", "warp_0"));
    CHECK_FALSE(globMatch("warp_*", "weft_0"));
    CHECK(globMatch("*_L[0-2]_?", "warp_L1_7"));
    CHECK_FALSE(globMatch("*_L[0-2]_?", "warp_L3_7"));
    CHECK(globMatch("binder_[!0]", "binder_3"));
    CHECK_FALSE(globMatch("binder_[!0]", "binder_0"));
    CHECK(globMatch("a\\*b", "a*b"));
    CHECK_FALSE(globMatch("a\\*b", "axb"));
    CHECK(globMatch("[", "["));  // no closing ']': an ordinary character
    CHECK(globMatch("*", ""));
    CHECK_FALSE(globMatch("?", ""));
    // Random well-formed patterns (literals, '*', '?', classes, escapes) against the system's
    // fnmatch() (unterminated classes are left out: glibc treats them inconsistently).
    std::mt19937 rng(3);
    const std::vector<std::string> tokens{"a", "b", "-", "*", "?", "[ab]", "[!a]", "[a-b]", "[^b]", "[]a]", "\\*", "\\a"};
    const std::string nameChars = "ab-*]";
    std::uniform_int_distribution<std::size_t> length(0, 5), tc(0, tokens.size() - 1), nc(0, nameChars.size() - 1);
    std::size_t agreed = 0;
    for (int k = 0; k < 200000; ++k) {
        std::string pattern, name;
        for (std::size_t i = length(rng); i > 0; --i) pattern += tokens[tc(rng)];
        for (std::size_t i = length(rng); i > 0; --i) name += nameChars[nc(rng)];
        const bool posix = fnmatch(pattern.c_str(), name.c_str(), 0) == 0;
        if (globMatch(pattern, name) != posix) {
            INFO("pattern '" << pattern << "', name '" << name << "': fnmatch " << posix);
            CHECK(globMatch(pattern, name) == posix);
            break;
        }
        ++agreed;
    }
    CHECK(agreed == 200000);
}
