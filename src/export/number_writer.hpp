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
