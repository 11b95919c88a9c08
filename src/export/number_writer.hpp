// Fast text output of numbers for the mesh writers.
#pragma once

#include <charconv>
#include <cstddef>
#include <ostream>
#include <string>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Lines of numbers formatted with std::to_chars (the shortest text that reads back to the same
/// double), gathered in a buffer and written in large blocks: iostream formatting of a million
/// points costs seconds.
class NumberWriter {
public:
    explicit NumberWriter(std::ostream& out) : out_(out) { buffer_.reserve(kBlock + 256); }
    ~NumberWriter() { flush(); }
    NumberWriter& text(const char* s)
    {
        buffer_ += s;
        return *this;
    }
    template <class T>
    NumberWriter& number(T x)
    {
        char digits[32];
        const auto r = std::to_chars(digits, digits + sizeof digits, x);
        buffer_.append(digits, r.ptr);
        return *this;
    }
    /// @p x in at most @p width characters: its shortest exact text when that fits (almost
    /// always), else rounded to as many significant digits as fit (at least 13 for widths >= 20).
    /// Abaqus and CalculiX read at most 20 characters of a number.
    NumberWriter& fitted(double x, std::size_t width)
    {
        char digits[32];
        auto r = std::to_chars(digits, digits + sizeof digits, x);
        for (int precision = 17; static_cast<std::size_t>(r.ptr - digits) > width && precision > 1; --precision)
            r = std::to_chars(digits, digits + sizeof digits, x, std::chars_format::general, precision);
        buffer_.append(digits, r.ptr);
        return *this;
    }
    NumberWriter& end()
    {
        buffer_ += '\n';
        if (buffer_.size() >= kBlock) flush();
        return *this;
    }
    void flush()
    {
        out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }

private:
    static constexpr std::size_t kBlock = 1 << 16;
    std::ostream& out_;
    std::string buffer_;
};


}  // namespace detail
TOWGEOM_END_NAMESPACE
