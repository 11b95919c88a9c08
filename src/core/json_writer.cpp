#include "core/json_writer.hpp"

#include <cmath>
#include <cstdio>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

void JsonWriter::separate()
{
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (!first_.empty()) {
        if (!first_.back()) out_ << ',';
        first_.back() = false;
    }
}

JsonWriter& JsonWriter::beginObject()
{
    separate();
    out_ << '{';
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::endObject()
{
    out_ << '}';
    first_.pop_back();
    return *this;
}

JsonWriter& JsonWriter::beginArray()
{
    separate();
    out_ << '[';
    first_.push_back(true);
    return *this;
}

JsonWriter& JsonWriter::endArray()
{
    out_ << ']';
    first_.pop_back();
    return *this;
}

JsonWriter& JsonWriter::key(const std::string& k)
{
    value(k);
    out_ << ':';
    afterKey_ = true;
    return *this;
}

JsonWriter& JsonWriter::value(const std::string& s)
{
    separate();
    out_ << '"';
    for (const char c : s) {
        switch (c) {
        case '"': out_ << "\\\""; break;
        case '\\': out_ << "\\\\"; break;
        case '\n': out_ << "\\n"; break;
        case '\t': out_ << "\\t"; break;
        case '\r': out_ << "\\r"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
                out_ << buf;
            } else {
                out_ << c;
            }
        }
    }
    out_ << '"';
    return *this;
}

JsonWriter& JsonWriter::value(double x)
{
    separate();
    if (!std::isfinite(x)) {
        out_ << "null";
        return *this;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    out_ << buf;
    return *this;
}

JsonWriter& JsonWriter::value(std::size_t n)
{
    separate();
    out_ << n;
    return *this;
}

JsonWriter& JsonWriter::value(bool b)
{
    separate();
    out_ << (b ? "true" : "false");
    return *this;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
