// A minimal streaming JSON writer for reports (commas and escaping handled here).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class JsonWriter {
public:
    explicit JsonWriter(std::ostream& out) : out_(out) {}

    JsonWriter& beginObject();
    JsonWriter& endObject();
    JsonWriter& beginArray();
    JsonWriter& endArray();
    JsonWriter& key(const std::string& k);
    JsonWriter& value(const std::string& s);
    JsonWriter& value(const char* s) { return value(std::string(s)); }
    /// Finite numbers with 17 significant digits; NaN and infinities as null.
    JsonWriter& value(double x);
    JsonWriter& value(std::size_t n);
    JsonWriter& value(bool b);

private:
    void separate();
    std::ostream& out_;
    std::vector<bool> first_;  // per open container: no element written yet
    bool afterKey_ = false;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
