// Bézier extraction as JSON for isogeometric codes (nlohmann-json, keys in the order written).
#include <nlohmann/json.hpp>

#include <ostream>

#include "towgeom/bezier_extraction.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeBezierJson(const BezierSurface& bezier, const std::string& tow, std::ostream& out)
{
    using Json = nlohmann::ordered_json;
    const auto points = [](const std::vector<Point3>& list) {
        Json a = Json::array();
        for (const Point3& p : list) a.push_back({p.x, p.y, p.z});
        return a;
    };
    Json j;
    j["tow"] = tow;
    j["u_degree"] = bezier.uDegree;
    j["v_degree"] = bezier.vDegree;
    j["u_functions"] = bezier.uFunctions;
    j["v_functions"] = bezier.vFunctions;
    j["v_periodic"] = bezier.vPeriodic;
    j["u_knots"] = bezier.uKnots;
    j["v_knots"] = bezier.vKnots;
    j["control_points"] = points(bezier.controlPoints);
    Json elements = Json::array();
    for (const BezierElement& e : bezier.elements)
        elements.push_back({{"u_span", e.uSpan},
                            {"v_span", e.vSpan},
                            {"u", {e.uMin, e.uMax}},
                            {"v", {e.vMin, e.vMax}},
                            {"functions", e.functions},
                            {"extraction", e.extraction},
                            {"bezier_points", points(e.controlPoints)}});
    j["elements"] = std::move(elements);
    out << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the Bézier extraction of tow '" + tow + "'");
}

TOWGEOM_END_NAMESPACE
