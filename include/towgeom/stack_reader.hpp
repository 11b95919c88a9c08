/// @file stack_reader.hpp
/// @brief Reading tow stacks from the plain-text `.stw` format.
///
/// The format, one tow per file:
/// @code
/// # comment lines start with '#'
/// tow warp_03            # optional; names the tow (default: the file stem)
/// 0.0  0.50 0.00         # a section: N lines "x y z" (whitespace- or comma-separated)
/// 0.0  0.25 0.43
/// ...
///                        # one or more blank lines end a section
/// 0.2  0.50 0.00         # next section, same N
/// ...
/// @endcode
/// Sections are in order along the tow. A closing point that repeats the section's first point
/// is dropped. Names may use letters, digits and `_ - . +`, may not start with a dot and have at
/// most 200 characters. Lines have at most 65536 characters; a UTF-8 byte order mark is skipped;
/// line ends may be `\n` or `\r\n`. Commas separate like spaces, but every comma must stand
/// between two numbers (`1, 2, 3`; not `1,,2,3` nor `1,2,3,`). Numbers are C locale decimals (`1.5`, `-2e-3`, `+4`); one
/// below the smallest double (e.g. `1e-400`) reads as its nearest value, 0.
#pragma once

#include <istream>
#include <string>

#include "towgeom/tow_stack.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Reads and validates one `.stw` file.
///
/// Streams the file line by line (memory grows with the number of points, not the file's size).
/// @throws towgeom::Error naming the file and line for a missing or unreadable file, an empty
///         file, binary data, an over-long line, a non-numeric token, a line with other than 3
///         coordinates, NaN/Inf, a coordinate beyond 1e100, and every rule of validateStack().
TOWGEOM_EXPORT TowStack readStackFile(const std::string& path);

/// Reads and validates a stack from a stream; @p sourceName is used in messages and
/// @p defaultName is the tow's name unless the stream holds a `tow NAME` line.
TOWGEOM_EXPORT TowStack readStack(std::istream& in, const std::string& sourceName, const std::string& defaultName);

/// Writes @p stack in the `.stw` format (17 significant digits, round-trips exactly).
TOWGEOM_EXPORT void writeStack(std::ostream& out, const TowStack& stack);

TOWGEOM_END_NAMESPACE
