// Shell patterns (`*`, `?`, `[...]`) as POSIX fnmatch() with no flags matches them, without
// depending on POSIX: tow names against --primary patterns.
#pragma once

#include <cstddef>
#include <string_view>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Matches the bracket expression starting at @p pattern[@p at] ('[') against @p c: sets
/// @p matched and moves @p at past the closing ']'. False when the expression has no closing ']'
/// (then '[' is an ordinary character).
inline bool matchBracket(std::string_view pattern, std::size_t& at, char c, bool& matched)
{
    std::size_t i = at + 1;
    const bool negate = i < pattern.size() && (pattern[i] == '!' || pattern[i] == '^');
    if (negate) ++i;
    bool found = false;
    bool first = true;
    while (i < pattern.size() && (first || pattern[i] != ']')) {
        first = false;
        char lo = pattern[i];
        if (lo == '\\' && i + 1 < pattern.size()) lo = pattern[++i];
        char hi = lo;
        if (i + 2 < pattern.size() && pattern[i + 1] == '-' && pattern[i + 2] != ']') {
            hi = pattern[i + 2];
            if (hi == '\\' && i + 3 < pattern.size()) hi = pattern[++i + 2];
            i += 2;
        }
        if (lo <= c && c <= hi) found = true;
        ++i;
    }
    if (i >= pattern.size()) return false;  // no closing ']'
    at = i + 1;
    matched = found != negate;
    return true;
}

/// True when @p name matches the shell pattern @p pattern: `*` any run of characters, `?` any one,
/// `[abc]`, `[a-z]`, `[!a]` (or `[^a]`) a character class, `\x` the character x.
inline bool globMatch(std::string_view pattern, std::string_view name)
{
    std::size_t p = 0, n = 0;
    std::size_t starP = std::string_view::npos, starN = 0;  // the last '*' and where it resumes
    while (n < name.size()) {
        if (p < pattern.size()) {
            const char c = pattern[p];
            if (c == '*') {
                starP = p++;
                starN = n;
                continue;
            }
            if (c == '?') {
                ++p;
                ++n;
                continue;
            }
            if (c == '[') {
                std::size_t at = p;
                bool matched = false;
                if (matchBracket(pattern, at, name[n], matched)) {
                    if (matched) {
                        p = at;
                        ++n;
                        continue;
                    }
                } else if (name[n] == '[') {
                    ++p;
                    ++n;
                    continue;
                }
            } else if (c != '\\' || p + 1 < pattern.size()) {  // a lone '\\' at the end matches nothing
                const bool escaped = c == '\\';
                if (name[n] == (escaped ? pattern[p + 1] : c)) {
                    p += escaped ? 2 : 1;
                    ++n;
                    continue;
                }
            }
        }
        if (starP == std::string_view::npos) return false;  // mismatch, no '*' to stretch
        p = starP + 1;
        n = ++starN;
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
