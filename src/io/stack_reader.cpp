#include "towgeom/stack_reader.hpp"

#include <charconv>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <system_error>

#include "core/section_geometry.hpp"
#include "io/input_file.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

constexpr std::size_t kMaxNameLength = 200;    // names become file names
constexpr std::size_t kMaxLineLength = 65536;  // longer is not a stack file; bounds memory

/// A token for a message: at most 40 characters, quoted.
std::string quoted(std::string_view token)
{
    std::string s(token.substr(0, 40));
    if (token.size() > 40) s += "...";
    return "'" + s + "'";
}

bool isNameChar(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.' || c == '+';
}

bool isSeparator(char c) { return c == ' ' || c == '\t' || c == ','; }

/// Drops a closing point that repeats the first one (within the duplicate tolerance of
/// validateStack), as the format allows.
void dropClosingPoint(std::vector<Point3>& section, std::vector<std::size_t>& lines)
{
    if (section.size() < 3) return;
    BoundingBox box;
    for (const Point3& p : section) box.add(p);
    if (distance(section.front(), section.back()) <= 1e-9 * box.diagonal()) {
        section.pop_back();
        lines.pop_back();
    }
}

class Parser {
public:
    Parser(const std::string& source, const std::string& defaultName)
    {
        stack_.source = source;
        stack_.name = defaultName;
    }

    void line(std::string& text, std::size_t number)
    {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte order mark
        for (char c : text) {
            const auto u = static_cast<unsigned char>(c);
            if (c == '\r')
                fail(ErrorCode::BinaryData, "carriage return inside a line: save the file with \\n or \\r\\n line ends",
                     number);
            if ((u < 0x20 && c != '\t') || u == 0x7f)
                fail(ErrorCode::BinaryData, "binary data (byte 0x" + hex(u) + "): not a text stack file",
                     number);
        }
        std::string_view view(text);
        if (const auto hash = view.find('#'); hash != std::string_view::npos) view = view.substr(0, hash);
        const auto first = view.find_first_not_of(" \t");
        if (first == std::string_view::npos) {
            // A blank line ends a section; a comment-only line does not.
            if (text.find('#') == std::string::npos) closeSection();
            return;
        }
        view = view.substr(first);
        if (view.substr(0, 3) == "tow" && (view.size() == 3 || view[3] == ' ' || view[3] == '\t')) {
            name(view.substr(3), number);
            return;
        }
        point(view, number);
    }

    TowStack finish()
    {
        closeSection();
        if (stack_.sections.empty()) fail(ErrorCode::EmptyInput, "no points: the file holds no section", 0);
        return std::move(stack_);
    }

private:
    static std::string hex(unsigned char u)
    {
        const char* digits = "0123456789abcdef";
        return {digits[u >> 4], digits[u & 15]};
    }

    [[noreturn]] void fail(ErrorCode code, const std::string& message, std::size_t number) const
    {
        throw Error(code, message, stack_.source, number);
    }

    void name(std::string_view rest, std::size_t number)
    {
        if (sawPoint_) fail(ErrorCode::BadName, "a 'tow NAME' line must come before the first point", number);
        if (sawName_) fail(ErrorCode::BadName, "a second 'tow NAME' line", number);
        const auto b = rest.find_first_not_of(" \t");
        const auto e = rest.find_last_not_of(" \t");
        if (b == std::string_view::npos) fail(ErrorCode::BadName, "'tow' line without a name", number);
        const std::string_view n = rest.substr(b, e - b + 1);
        bool ok = n.front() != '.';
        for (char c : n) ok = ok && isNameChar(c);
        if (!ok)
            fail(ErrorCode::BadName,
                 "tow name " + quoted(n) + " may only use letters, digits and _ - . + and not start with '.'",
                 number);
        if (n.size() > kMaxNameLength)
            fail(ErrorCode::BadName, "tow name is longer than " + std::to_string(kMaxNameLength) + " characters", number);
        stack_.name = std::string(n);
        sawName_ = true;
    }

    void point(std::string_view view, std::size_t number)
    {
        double xyz[3] = {0, 0, 0};
        std::size_t count = 0;
        std::size_t pos = 0;
        bool fieldOpen = true;  // a comma opens a field that a number must fill
        while (pos < view.size()) {
            while (pos < view.size() && isSeparator(view[pos])) {
                if (view[pos] == ',') {
                    if (fieldOpen) fail(ErrorCode::NonNumeric, "empty field: a comma with no number before it", number);
                    fieldOpen = true;
                }
                ++pos;
            }
            if (pos == view.size()) break;
            fieldOpen = false;
            std::size_t end = pos;
            while (end < view.size() && !isSeparator(view[end])) ++end;
            const std::string_view token = view.substr(pos, end - pos);
            const double value = number_(token, number);
            if (count < 3) xyz[count] = value;
            ++count;
            pos = end;
        }
        if (fieldOpen && count > 0) fail(ErrorCode::NonNumeric, "empty field: a comma with no number after it", number);
        if (count != 3)
            fail(ErrorCode::WrongCoordinateCount,
                 "expected 3 coordinates 'x y z', found " + std::to_string(count), number);
        current_.push_back({xyz[0], xyz[1], xyz[2]});
        currentLines_.push_back(number);
        sawPoint_ = true;
    }

    double number_(std::string_view token, std::size_t number) const
    {
        std::string_view digits = token;
        if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
        double value = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range && end == digits.data() + digits.size()) {
            // Out of range is either overflow (refused) or underflow: below the smallest double,
            // whose nearest value is 0 (or a denormal), which is what the file means.
            const double nearest = std::strtod(std::string(digits).c_str(), nullptr);
            if (std::fabs(nearest) >= 1.0)
                fail(ErrorCode::OutOfRange, "coordinate " + quoted(token) + " is beyond +-1e100", number);
            return nearest;
        }
        if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
            fail(ErrorCode::NonNumeric, quoted(token) + " is not a number", number);
        if (!std::isfinite(value)) fail(ErrorCode::NonFinite, "coordinate " + quoted(token) + " is not finite", number);
        if (std::fabs(value) > detail::kMaxCoordinate)
            fail(ErrorCode::OutOfRange, "coordinate " + quoted(token) + " is beyond +-1e100", number);
        return value;
    }

    void closeSection()
    {
        if (current_.empty()) return;
        dropClosingPoint(current_, currentLines_);
        stack_.sections.push_back(std::move(current_));
        stack_.lines.push_back(std::move(currentLines_));
        current_.clear();
        currentLines_.clear();
    }

    TowStack stack_;
    std::vector<Point3> current_;
    std::vector<std::size_t> currentLines_;
    bool sawPoint_ = false;
    bool sawName_ = false;
};

}  // namespace

TowStack readStack(std::istream& in, const std::string& sourceName, const std::string& defaultName)
{
    Parser parser(sourceName, defaultName);
    std::vector<char> buffer(kMaxLineLength + 2);
    std::string text;
    std::size_t number = 0;
    for (;;) {
        // Bounded lines: a file without line breaks cannot make the reader hold all of it.
        in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (in.bad()) throw Error(ErrorCode::FileUnreadable, "read error after line " + std::to_string(number), sourceName);
        if (in.fail() && !in.eof())
            throw Error(ErrorCode::LineTooLong,
                        "line longer than " + std::to_string(kMaxLineLength) + " characters: not a stack file",
                        sourceName, number + 1);
        if (got == 0 && in.eof()) break;
        const bool delimited = !in.eof();  // the newline was read and counted in gcount()
        text.assign(buffer.data(), delimited ? got - 1 : got);
        parser.line(text, ++number);
        if (in.eof()) break;
    }
    TowStack stack = parser.finish();
    validateStack(stack);
    return stack;
}

TowStack readStackFile(const std::string& path)
{
    namespace fs = std::filesystem;
    std::ifstream in = detail::openInputFile(path, "a stack file");
    std::string stem = fs::path(path).stem().string();
    bool stemOk = !stem.empty() && stem.front() != '.';
    for (char c : stem) stemOk = stemOk && isNameChar(c);
    // An unusual file name is not an error as long as the file names the tow itself.
    TowStack stack = readStack(in, path, stemOk ? stem : std::string());
    if (stack.name.empty())
        throw Error(ErrorCode::BadName,
                    "the file name is not a usable tow name; add a 'tow NAME' line (letters, digits, _ - . +)", path);
    return stack;
}

void writeStack(std::ostream& out, const TowStack& stack)
{
    out << "# towgeom tow stack: " << stack.sectionCount() << " sections x " << stack.pointsPerSection()
        << " points\n";
    if (!stack.name.empty()) out << "tow " << stack.name << "\n";
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (std::size_t i = 0; i < stack.sections.size(); ++i) {
        if (i > 0) out << "\n";
        for (const Point3& p : stack.sections[i]) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
}

TOWGEOM_END_NAMESPACE
