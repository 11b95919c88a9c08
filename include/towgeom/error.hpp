/// @file error.hpp
/// @brief The one exception type of towgeom: towgeom::Error, with a code and a source location.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// What went wrong. Every failure the library reports carries one of these codes.
enum class ErrorCode {
    FileNotFound,             ///< The input path does not exist.
    FileUnreadable,           ///< The input exists but cannot be read (permissions, a directory, ...).
    EmptyInput,               ///< The input holds no data points.
    BinaryData,               ///< The input holds NUL or control bytes: not a text stack file.
    NonNumeric,               ///< A token that should be a number is not one.
    WrongCoordinateCount,     ///< A point line does not hold exactly three coordinates.
    NonFinite,                ///< A coordinate is NaN or infinite.
    OutOfRange,               ///< A coordinate's magnitude exceeds 1e100, or a section is less than 1e-100 across.
    BadName,                  ///< A `tow NAME` line is malformed or the name is unsafe as a file name.
    UnequalSectionSize,       ///< Sections do not all have the same number of points.
    TooFewSections,           ///< Fewer than 4 sections.
    TooFewPoints,             ///< Fewer than 6 points per section.
    DuplicatePoint,           ///< Two consecutive points of a section coincide.
    ZeroAreaSection,          ///< A section encloses (almost) no area: its points are collinear.
    SelfIntersectingSection,  ///< A section's polygon crosses itself.
    InconsistentOrientation,  ///< Sections do not all go around the tow in the same direction.
    InconsistentStart,        ///< Consecutive sections correspond point by point under no cyclic renumbering.
    LineTooLong,              ///< A line is longer than 65536 characters: not a stack file.
    DegenerateTow,            ///< Consecutive sections coincide, so the tow has no length there.
    InvalidArgument,          ///< A caller-supplied option or argument is out of its domain.
    FitFailed,                ///< The surface fit could not be computed (singular system, ...).
    WriteFailed,              ///< An output file could not be written.
    Internal,                 ///< A geometry kernel failed unexpectedly; the message says where.
    TooLarge,                 ///< The mesh or tessellation asked for would exceed its size limit
                              ///< (MeshOptions::maxTriangles); refused before it is made, the
                              ///< message gives the estimate and the limit.
    MalformedReport,          ///< A report read back (JSON, or a solver's output: readEffectiveStiffness()) is
                              ///< malformed, or is not one of the tows given.
    Cancelled,                ///< Progress::cancel() stopped the work; no result was made.
    EngineUnavailable,        ///< An engine loaded when first needed (Gmsh's library, for
                              ///< meshVolumes()) could not be loaded; the message names its package.
    Unsupported               ///< Valid input that this version cannot handle yet (e.g. a
                              ///< trimmed B-rep of a loop across an end cap); the message says what.
};

/// A short, stable, machine-readable name of a code, e.g. "non_numeric".
TOWGEOM_EXPORT const char* errorCodeName(ErrorCode code) noexcept;

/// The exception thrown by every towgeom function on bad input or failure.
///
/// `what()` reads `FILE:LINE: message` when a file and line are known, `FILE: message` when only
/// the file is known, and `message` otherwise, so it can be shown to a user as it is.
class TOWGEOM_EXPORT Error : public std::runtime_error {
public:
    /// @param code    what went wrong
    /// @param message a sentence for a person, without the location prefix
    /// @param file    the file (or tow name) concerned, empty if none
    /// @param line    1-based line in @p file, 0 if not known
    Error(ErrorCode code, const std::string& message, std::string file = {}, std::size_t line = 0);

    /// What went wrong.
    ErrorCode code() const noexcept { return code_; }
    /// The message without the location prefix.
    const std::string& message() const noexcept { return message_; }
    /// The file (or tow) concerned; empty if none.
    const std::string& file() const noexcept { return file_; }
    /// 1-based line in file(); 0 if not known.
    std::size_t line() const noexcept { return line_; }

private:
    ErrorCode code_;
    std::string message_;
    std::string file_;
    std::size_t line_;
};

TOWGEOM_END_NAMESPACE
