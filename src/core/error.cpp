#include "towgeom/error.hpp"

#include <utility>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {
std::string locate(const std::string& message, const std::string& file, std::size_t line)
{
    if (file.empty()) return message;
    if (line == 0) return file + ": " + message;
    return file + ":" + std::to_string(line) + ": " + message;
}
}  // namespace

Error::Error(ErrorCode code, const std::string& message, std::string file, std::size_t line)
    : std::runtime_error(locate(message, file, line)),
      code_(code),
      message_(message),
      file_(std::move(file)),
      line_(line)
{
}

const char* errorCodeName(ErrorCode code) noexcept
{
    switch (code) {
    case ErrorCode::FileNotFound: return "file_not_found";
    case ErrorCode::FileUnreadable: return "file_unreadable";
    case ErrorCode::EmptyInput: return "empty_input";
    case ErrorCode::BinaryData: return "binary_data";
    case ErrorCode::NonNumeric: return "non_numeric";
    case ErrorCode::WrongCoordinateCount: return "wrong_coordinate_count";
    case ErrorCode::NonFinite: return "non_finite";
    case ErrorCode::OutOfRange: return "out_of_range";
    case ErrorCode::BadName: return "bad_name";
    case ErrorCode::UnequalSectionSize: return "unequal_section_size";
    case ErrorCode::TooFewSections: return "too_few_sections";
    case ErrorCode::TooFewPoints: return "too_few_points";
    case ErrorCode::DuplicatePoint: return "duplicate_point";
    case ErrorCode::ZeroAreaSection: return "zero_area_section";
    case ErrorCode::SelfIntersectingSection: return "self_intersecting_section";
    case ErrorCode::InconsistentOrientation: return "inconsistent_orientation";
    case ErrorCode::InconsistentStart: return "inconsistent_start";
    case ErrorCode::LineTooLong: return "line_too_long";
    case ErrorCode::DegenerateTow: return "degenerate_tow";
    case ErrorCode::InvalidArgument: return "invalid_argument";
    case ErrorCode::FitFailed: return "fit_failed";
    case ErrorCode::WriteFailed: return "write_failed";
    case ErrorCode::Internal: return "internal";
    case ErrorCode::TooLarge: return "too_large";
    case ErrorCode::MalformedReport: return "malformed_report";
    case ErrorCode::Cancelled: return "cancelled";
    case ErrorCode::EngineUnavailable: return "engine_unavailable";
    case ErrorCode::Unsupported: return "unsupported";
    }
    return "unknown";
}

TOWGEOM_END_NAMESPACE
