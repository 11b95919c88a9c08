// IntersectionReport <-> JSON (nlohmann-json), exact: doubles are written as the shortest text
// that reads back to the same double.
#include "towgeom/intersection_report_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <istream>
#include <memory>
#include <ostream>

#include "intersect/intersection_loop_data.hpp"
#include "intersect/loop_tracing.hpp"
#include "intersect/textile_frame.hpp"
#include "io/input_file.hpp"
#include "io/output_files.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Json = nlohmann::json;

constexpr const char* kFormat = "towgeom-intersections";
constexpr int kVersion = 1;
constexpr double kVPeriods = 100.0;  // how far an unwrapped v may lie from the period

/// The same tows and the same points in the same order.
bool sameLoop(const IntersectionLoop& a, const IntersectionLoop& b)
{
    if (a.towA() != b.towA() || a.towB() != b.towB() || a.points().size() != b.points().size()) return false;
    for (std::size_t k = 0; k < a.points().size(); ++k) {
        const Point3 &p = a.points()[k].point, &q = b.points()[k].point;
        if (!(p.x == q.x && p.y == q.y && p.z == q.z)) return false;
    }
    return true;
}

const char* kindName(PairFinding::Kind k)
{
    switch (k) {
    case PairFinding::Kind::Touching: return "touching";
    case PairFinding::Kind::Nested: return "nested";
    case PairFinding::Kind::Contact: return "contact";
    case PairFinding::Kind::Incomplete: return "incomplete";
    }
    return "touching";
}

/// The largest loop tolerance a report holds, relative to the smaller tow's size: beyond it the
/// reader's check that the points lie on the tows' surfaces would mean nothing.
constexpr double kMaxRelativeTolerance = 1e-2;

Json toJson(const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    detail::checkReportTows(tows, report);
    for (std::size_t k = 0; k < report.loops.size(); ++k) {
        const IntersectionLoop& l = report.loops[k];
        if (l.tolerance() > kMaxRelativeTolerance * std::min(tows[l.towA()].towSize(), tows[l.towB()].towSize()))
            throw Error(ErrorCode::InvalidArgument, "intersection loop " + std::to_string(k) +
                                                        " was computed with a tolerance over 1e-2 of the tows' size: a report "
                                                        "cannot hold it (its points could not be checked on reading)");
    }
    Json j;
    j["format"] = kFormat;
    j["version"] = kVersion;
    Json names = Json::array();
    for (const TowSurface& t : tows) names.push_back(t.name());
    j["tows"] = std::move(names);
    Json loops = Json::array();
    for (const IntersectionLoop& l : report.loops) {
        const IntersectionLoop::Data& d = l.data();
        Json points = Json::array();
        for (std::size_t k = 0; k < d.points.size(); ++k) {
            const LoopPoint& p = d.points[k];
            points.push_back({p.point.x, p.point.y, p.point.z, p.onA.u, p.onA.v, p.onB.u, p.onB.v, d.cumulative[k]});
        }
        Json loop = {{"tow_a", d.towA}, {"tow_b", d.towB}, {"closed", d.closed}, {"open_reason", d.openReason},
                     {"tolerance", d.tolerance}, {"length", d.cumulative.back()}, {"points", std::move(points)}};
        loops.push_back(std::move(loop));
    }
    j["loops"] = std::move(loops);
    Json findings = Json::array();
    for (const PairFinding& f : report.findings)
        findings.push_back({{"tow_a", f.towA}, {"tow_b", f.towB}, {"kind", kindName(f.kind)}, {"message", f.message}});
    j["findings"] = std::move(findings);
    j["counts"] = {{"tow_pairs", report.towPairs}, {"pairs_tested", report.pairsTested}, {"window_pairs", report.windowPairs},
                   {"seeds", report.seeds}, {"walks", report.walks}};
    j["timings_ms"] = {{"broad_phase", report.timings.broadPhase}, {"exact", report.timings.exact}};
    return j;
}

/// Reads one report, each failure a MalformedReport naming the source and where.
class ReportReader {
public:
    ReportReader(const std::vector<TowSurface>& tows, const std::string& source) : tows_(tows), source_(source) {}

    IntersectionReport read(std::istream& in)
    {
        try {
            return readJson(in);
        } catch (const Json::exception& e) {  // a number out of double's range, ...
            fail("not a readable report (" + std::string(e.what()) + ")");
        }
    }

private:
    IntersectionReport readJson(std::istream& in)
    {
        Json j;
        try {
            j = Json::parse(in);
        } catch (const Json::parse_error& e) {
            fail("not JSON (" + std::string(e.what()) + ")");
        }
        if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
            fail(std::string("not a towgeom intersection report (\"format\" is not \"") + kFormat + "\")");
        if (!j.contains("version") || j["version"] != kVersion)
            fail("report version " + (j.contains("version") ? j["version"].dump() : std::string("missing")) +
                 ", this towgeom reads version " + std::to_string(kVersion));
        checkTows(field(j, "tows", "the report"));
        IntersectionReport report;
        const Json& loops = field(j, "loops", "the report");
        if (!loops.is_array()) fail("\"loops\" is not an array");
        for (std::size_t k = 0; k < loops.size(); ++k) {
            report.loops.push_back(loop(loops[k], "loop " + std::to_string(k)));
            for (std::size_t i = 0; i < k; ++i)
                if (sameLoop(report.loops[i], report.loops[k]))
                    fail("loop " + std::to_string(k) + " repeats loop " + std::to_string(i));
        }
        const Json& findings = field(j, "findings", "the report");
        if (!findings.is_array()) fail("\"findings\" is not an array");
        for (std::size_t k = 0; k < findings.size(); ++k) report.findings.push_back(finding(findings[k], "finding " + std::to_string(k)));
        const Json& counts = field(j, "counts", "the report");
        report.towPairs = count(counts, "tow_pairs");
        report.pairsTested = count(counts, "pairs_tested");
        report.windowPairs = count(counts, "window_pairs");
        report.seeds = count(counts, "seeds");
        report.walks = count(counts, "walks");
        return report;
    }

    [[noreturn]] void fail(const std::string& what) const { throw Error(ErrorCode::MalformedReport, what, source_); }

    const Json& field(const Json& object, const char* key, const std::string& where) const
    {
        if (!object.is_object() || !object.contains(key)) fail(where + " has no \"" + key + "\"");
        return object[key];
    }

    std::size_t count(const Json& object, const char* key) const
    {
        const Json& v = field(object, key, "\"counts\"");
        if (!v.is_number_unsigned()) fail(std::string("\"counts\".\"") + key + "\" is not a count");
        return v.get<std::size_t>();
    }

    std::size_t towIndex(const Json& object, const char* key, const std::string& where) const
    {
        const Json& v = field(object, key, where);
        if (!v.is_number_unsigned() || v.get<std::size_t>() >= tows_.size())
            fail(where + ": \"" + key + "\" is not a tow index below " + std::to_string(tows_.size()));
        return v.get<std::size_t>();
    }

    double number(const Json& v, const std::string& where) const
    {
        if (!v.is_number()) fail(where + " is not a number");
        const double x = v.get<double>();
        if (!std::isfinite(x)) fail(where + " is not finite");
        return x;
    }

    void checkTows(const Json& names) const
    {
        std::vector<std::string> given;
        for (const TowSurface& t : tows_) given.push_back(t.name());
        std::vector<std::string> written;
        if (names.is_array())
            for (const Json& n : names)
                if (n.is_string()) written.push_back(n.get<std::string>());
        if (!names.is_array() || written.size() != names.size()) fail("\"tows\" is not an array of names");
        if (written == given) return;
        const auto list = [](const std::vector<std::string>& v) {
            std::string s;
            for (std::size_t k = 0; k < v.size() && k < 4; ++k) s += (k ? ", '" : "'") + v[k] + "'";
            return v.size() > 4 ? s + ", ... (" + std::to_string(v.size()) + " tows)" : s;
        };
        fail("the report is for the tows " + list(written) + ", not for the tows given: " + list(given) +
             " (the same tows, in the same order, are needed)");
    }

    IntersectionLoop loop(const Json& l, const std::string& where) const
    {
        const std::size_t a = towIndex(l, "tow_a", where), b = towIndex(l, "tow_b", where);
        if (a >= b) fail(where + ": \"tow_a\" is not below \"tow_b\"");
        auto d = std::make_shared<IntersectionLoop::Data>(tows_[a], tows_[b]);
        d->towA = a;
        d->towB = b;
        const Json& closed = field(l, "closed", where);
        const Json& reason = field(l, "open_reason", where);
        if (!closed.is_boolean() || !reason.is_string()) fail(where + ": \"closed\" or \"open_reason\" has the wrong type");
        d->closed = closed.get<bool>();
        d->openReason = reason.get<std::string>();
        IntersectionLoop::OpenKind kind = IntersectionLoop::OpenKind::None;
        if (d->closed ? !d->openReason.empty() : !detail::openKindOf(d->openReason, kind))
            fail(where + ": \"open_reason\" is " + (d->closed ? "not empty for a closed loop" : "none of towgeom's reasons"));
        d->tolerance = number(field(l, "tolerance", where), where + " tolerance");
        const double size = std::min(tows_[a].towSize(), tows_[b].towSize());
        if (!(d->tolerance > 0.0) || d->tolerance > kMaxRelativeTolerance * size)
            fail(where + ": the tolerance is not positive and at most 1e-2 of the tows' size");
        const Json& points = field(l, "points", where);
        if (!points.is_array() || points.size() < (d->closed ? 3u : 2u))
            fail(where + ": \"points\" is not an array of at least " + (d->closed ? "3" : "2") + " points");
        const ParameterRange ra = tows_[a].parameterRange(), rb = tows_[b].parameterRange();
        for (std::size_t k = 0; k < points.size(); ++k) {
            const std::string at = where + " point " + std::to_string(k);
            const Json& p = points[k];
            if (!p.is_array() || p.size() != 8) fail(at + " is not [x, y, z, uA, vA, uB, vB, s]");
            double x[8];
            for (std::size_t i = 0; i < 8; ++i) x[i] = number(p[i], at);
            // u beyond the tube's range lies on an end cap (LoopPoint), up to its centre.
            const auto inU = [](double u, const ParameterRange& r, const TowSurface& t) {
                const double slack = 1e-9 * (r.uMax - r.uMin);
                const detail::TowCaps& caps = t.impl().caps;
                return u >= caps.uLow() - slack && u <= caps.uHigh() + slack;
            };
            // v is unwrapped along a loop (it may go round the tow a few times), never far.
            const auto nearV = [](double v, const ParameterRange& r) {
                return v >= r.vMin - kVPeriods * r.vPeriod() && v <= r.vMax + kVPeriods * r.vPeriod();
            };
            if (!inU(x[3], ra, tows_[a]) || !inU(x[5], rb, tows_[b])) fail(at + ": u lies off the tow's parameter range and its caps");
            if (!nearV(x[4], ra) || !nearV(x[6], rb)) fail(at + ": v lies more than 100 periods off the tow's");
            if (k == 0 && x[7] != 0.0) fail(at + ": the arc length s of the first point is not 0");
            if (k > 0) checkStep(d->points.back().point, {x[0], x[1], x[2]}, x[7] - d->cumulative.back(), at);
            d->points.push_back({{x[0], x[1], x[2]}, {x[3], x[4]}, {x[5], x[6]}});
            d->cumulative.push_back(x[7]);
            d->maxDistanceA = std::max(d->maxDistanceA, distance(d->points.back().point, detail::closedPoint(tows_[a], x[3], x[4])));
            d->maxDistanceB = std::max(d->maxDistanceB, distance(d->points.back().point, detail::closedPoint(tows_[b], x[5], x[6])));
        }
        const double length = number(field(l, "length", where), where + " length");
        if (d->closed) {
            checkStep(d->points.back().point, d->points.front().point, length - d->cumulative.back(), where + " closing chord");
            d->cumulative.push_back(length);
        } else if (length != d->cumulative.back()) {
            fail(where + ": \"length\" of an open curve is not the last point's arc length");
        }
        if (!(length > 0.0)) fail(where + " has no length");
        const auto offBy = [&](double gap, const TowSurface& t) {
            return gap > 1000.0 * d->tolerance + 1e-6 * t.towSize();
        };
        if (offBy(d->maxDistanceA, tows_[a]) || offBy(d->maxDistanceB, tows_[b]))
            fail(where + ": its points lie off the surfaces of tows '" + tows_[a].name() + "' and '" + tows_[b].name() +
                 "' (up to " + std::to_string(std::max(d->maxDistanceA, d->maxDistanceB)) +
                 "): the report is not for these tows' geometry");
        return IntersectionLoop(std::move(d));
    }

    /// Refuses an arc length step @p ds that is not the distance from @p p to @p q (to 1e-9 of
    /// it, plus rounding).
    void checkStep(const Point3& p, const Point3& q, double ds, const std::string& at) const
    {
        const double d = distance(p, q);
        if (!(std::abs(ds - d) <= 1e-9 * d + 1e-14 * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + d)))
            fail(at + ": the arc length grows by " + std::to_string(ds) + " where the points are " + std::to_string(d) +
                 " apart");
    }

    PairFinding finding(const Json& f, const std::string& where) const
    {
        PairFinding out;
        out.towA = towIndex(f, "tow_a", where);
        out.towB = towIndex(f, "tow_b", where);
        const Json& kind = field(f, "kind", where);
        const Json& message = field(f, "message", where);
        if (!kind.is_string() || !message.is_string()) fail(where + ": \"kind\" or \"message\" is not a string");
        const std::string k = kind.get<std::string>();
        if (k == "touching") out.kind = PairFinding::Kind::Touching;
        else if (k == "nested") out.kind = PairFinding::Kind::Nested;
        else if (k == "contact") out.kind = PairFinding::Kind::Contact;
        else if (k == "incomplete") out.kind = PairFinding::Kind::Incomplete;
        else fail(where + ": unknown kind \"" + k + "\" (touching, nested, contact, incomplete)");
        out.message = message.get<std::string>();
        return out;
    }

    const std::vector<TowSurface>& tows_;
    std::string source_;
};

}  // namespace

namespace {

/// The report's JSON text; a tow name that is not UTF-8 is refused (InvalidArgument).
std::string jsonText(const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    try {
        return toJson(report, tows).dump() + '\n';
    } catch (const Json::type_error& e) {
        throw Error(ErrorCode::InvalidArgument, std::string("a tow name cannot be written as JSON: ") + e.what());
    }
}

}  // namespace

void writeIntersectionReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, std::ostream& out)
{
    out << jsonText(report, tows);
}

void writeIntersectionReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, const std::string& path)
{
    const std::string text = jsonText(report, tows);  // refuses a bad report before any file is made
    detail::OutputFiles files;
    files.open(path) << text;
    files.commit();
}

IntersectionReport readIntersectionReport(std::istream& in, const std::vector<TowSurface>& tows, const std::string& sourceName)
{
    return ReportReader(tows, sourceName).read(in);
}

IntersectionReport readIntersectionReport(const std::string& path, const std::vector<TowSurface>& tows)
{
    std::ifstream in = detail::openInputFile(path, "an intersection report");
    return readIntersectionReport(in, tows, path);
}

TOWGEOM_END_NAMESPACE
