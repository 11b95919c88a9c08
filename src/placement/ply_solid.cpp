// Trivariate NURBS ply solids between a surface and its offset: evaluation (rational, with the
// Jacobian), volume by Gauss-Legendre per knot span, JSON for IGA codes and sampled VTK.
#include <math.hxx>
#include <math_Vector.hxx>

#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <vector>

#include "placement/nurbs_basis.hpp"
#include "towgeom/error.hpp"
#include "towgeom/nurbs_offset.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// The volume's point and its three parameter derivatives at (u, v, w).
struct VolumePoint {
    Point3 x;
    Vector3 d[3];
};

void checkVolume(const NurbsVolume& vol)
{
    for (int k = 0; k < 3; ++k) detail::checkKnots(vol.knots[k], vol.degree[k], vol.count[k], "volume");
    const std::size_t n = vol.count[0] * vol.count[1] * vol.count[2];
    if (vol.poles.size() != n) throw Error(ErrorCode::InvalidArgument, "NURBS volume: the poles are not count[0] x count[1] x count[2]");
    detail::checkWeights(vol.weights, n, "volume");
    detail::checkPoles(vol.poles, "volume");
}

/// The volume's point from the basis rows of its three directions at one parameter triple (the
/// rows are computed once per parameter of a grid, not once per grid point).
VolumePoint combine(const NurbsVolume& vol, const detail::BasisRow& bu, const detail::BasisRow& bv, const detail::BasisRow& bw)
{
    const detail::BasisRow* b[3] = {&bu, &bv, &bw};
    // A = sum N N N w P and W = sum N N N w, with their three derivatives.
    Vector3 a{}, da[3]{};
    double W = 0.0, dW[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < b[0]->values.size(); ++i)
        for (std::size_t j = 0; j < b[1]->values.size(); ++j)
            for (std::size_t k = 0; k < b[2]->values.size(); ++k) {
                const std::size_t index = ((b[0]->first + i) * vol.count[1] + b[1]->first + j) * vol.count[2] + b[2]->first + k;
                const double wt = vol.weights[index];
                const Point3& p = vol.poles[index];
                const Vector3 pv{p.x, p.y, p.z};
                const double n = b[0]->values[i] * b[1]->values[j] * b[2]->values[k];
                const double dn[3] = {b[0]->slopes[i] * b[1]->values[j] * b[2]->values[k], b[0]->values[i] * b[1]->slopes[j] * b[2]->values[k],
                                      b[0]->values[i] * b[1]->values[j] * b[2]->slopes[k]};
                a = a + (n * wt) * pv;
                W += n * wt;
                for (int c = 0; c < 3; ++c) {
                    da[c] = da[c] + (dn[c] * wt) * pv;
                    dW[c] += dn[c] * wt;
                }
            }
    VolumePoint r;
    const Vector3 x = (1.0 / W) * a;
    r.x = {x.x, x.y, x.z};
    for (int c = 0; c < 3; ++c) r.d[c] = (1.0 / W) * (da[c] - dW[c] * x);
    return r;
}

VolumePoint evaluate(const NurbsVolume& vol, double u, double v, double w)
{
    return combine(vol, detail::bsplineBasis(vol.knots[0], vol.degree[0], u), detail::bsplineBasis(vol.knots[1], vol.degree[1], v),
                   detail::bsplineBasis(vol.knots[2], vol.degree[2], w));
}

/// The basis rows of direction @p c at each of @p at.
std::vector<detail::BasisRow> rowsAt(const NurbsVolume& vol, std::size_t c, const std::vector<double>& at)
{
    std::vector<detail::BasisRow> rows;
    rows.reserve(at.size());
    for (double t : at) rows.push_back(detail::bsplineBasis(vol.knots[c], vol.degree[c], t));
    return rows;
}

std::vector<std::pair<double, double>> spansOf(const std::vector<double>& knots)
{
    std::vector<std::pair<double, double>> s;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
        if (knots[k + 1] > knots[k]) s.emplace_back(knots[k], knots[k + 1]);
    return s;
}

}  // namespace

Point3 NurbsVolume::point(double u, double v, double w) const
{
    checkVolume(*this);
    return evaluate(*this, u, v, w).x;
}

double NurbsVolume::jacobian(double u, double v, double w) const
{
    checkVolume(*this);
    const VolumePoint p = evaluate(*this, u, v, w);
    return dot(p.d[0], cross(p.d[1], p.d[2]));
}

namespace {

/// Whether @p a and @p b share degrees, knots, pole counts and (to rounding) weights.
bool sameParametrisation(const NurbsSurface& a, const NurbsSurface& b)
{
    if (a.uDegree != b.uDegree || a.vDegree != b.vDegree || a.uKnots != b.uKnots || a.vKnots != b.vKnots || a.uCount != b.uCount ||
        a.vCount != b.vCount || a.poles.size() != b.poles.size() || a.weights.size() != b.weights.size())
        return false;
    for (std::size_t k = 0; k < a.weights.size(); ++k)
        if (!(std::abs(a.weights[k] - b.weights[k]) <= 1e-12 * std::abs(a.weights[k]))) return false;
    return true;
}

/// The ply volume of degree @p layers.size() - 1 in w through the pole layers @p layers.
NurbsVolume plyThrough(const NurbsSurface& base, const std::vector<const std::vector<Point3>*>& layers)
{
    const int degree = static_cast<int>(layers.size()) - 1;
    NurbsVolume vol;
    vol.degree[0] = base.uDegree;
    vol.degree[1] = base.vDegree;
    vol.degree[2] = degree;
    vol.knots[0] = base.uKnots;
    vol.knots[1] = base.vKnots;
    vol.knots[2].assign(static_cast<std::size_t>(degree + 1), 0.0);
    vol.knots[2].resize(static_cast<std::size_t>(2 * degree + 2), 1.0);
    vol.count[0] = base.uCount;
    vol.count[1] = base.vCount;
    vol.count[2] = layers.size();
    for (std::size_t k = 0; k < base.poles.size(); ++k)
        for (const std::vector<Point3>* layer : layers) {
            vol.poles.push_back((*layer)[k]);
            vol.weights.push_back(base.weights[k]);
        }
    checkVolume(vol);
    return vol;
}

}  // namespace

NurbsVolume plySolid(const NurbsSurface& base, const NurbsSurface& top)
{
    if (!sameParametrisation(base, top))
        throw Error(ErrorCode::InvalidArgument, "plySolid: the two surfaces must share their degrees, knots and weights (an "
                                                "offset from offsetSurface() and its base do)");
    return plyThrough(base, {&base.poles, &top.poles});
}

NurbsVolume plySolid(const NurbsSurface& base, const NurbsSurface& middle, const NurbsSurface& top)
{
    if (!sameParametrisation(base, middle) || !sameParametrisation(base, top))
        throw Error(ErrorCode::InvalidArgument, "plySolid: the three surfaces must share their degrees, knots and weights (withKnotsOf() "
                                                "gives surfaces offset separately common knots)");
    std::vector<Point3> inner(base.poles.size());
    for (std::size_t k = 0; k < inner.size(); ++k) inner[k] = 2.0 * middle.poles[k] - 0.5 * (base.poles[k] + top.poles[k]);
    return plyThrough(base, {&base.poles, &inner, &top.poles});
}

VolumeMeasure measureVolume(const NurbsVolume& vol, int points)
{
    checkVolume(vol);
    if (points < 1 || points > 40) throw Error(ErrorCode::InvalidArgument, "measureVolume: 1 to 40 points per span");
    math_Vector gx(1, points), gw(1, points);
    math::GaussPoints(points, gx);
    math::GaussWeights(points, gw);
    VolumeMeasure m;
    m.minJacobian = std::numeric_limits<double>::infinity();
    m.maxJacobian = -std::numeric_limits<double>::infinity();
    std::array<double, 3> minAt{}, maxAt{};
    Point3 minPoint, maxPoint;
    // Per direction: the Gauss points of every span, each with its weight times the span's half
    // length, and the basis rows there.
    std::array<std::vector<double>, 3> at, weight;
    std::array<std::vector<detail::BasisRow>, 3> rows;
    for (std::size_t c = 0; c < 3; ++c) {
        for (const auto& [t0, t1] : spansOf(vol.knots[c]))
            for (int i = 1; i <= points; ++i) {
                at[c].push_back(t0 + 0.5 * (t1 - t0) * (1.0 + gx(i)));
                weight[c].push_back(0.5 * (t1 - t0) * gw(i));
            }
        rows[c] = rowsAt(vol, c, at[c]);
    }
    for (std::size_t i = 0; i < at[0].size(); ++i)
        for (std::size_t j = 0; j < at[1].size(); ++j)
            for (std::size_t k = 0; k < at[2].size(); ++k) {
                const std::array<double, 3> here{at[0][i], at[1][j], at[2][k]};
                const VolumePoint p = combine(vol, rows[0][i], rows[1][j], rows[2][k]);
                const double jac = dot(p.d[0], cross(p.d[1], p.d[2]));
                if (jac < m.minJacobian) {
                    m.minJacobian = jac;
                    minAt = here;
                    minPoint = p.x;
                }
                if (jac > m.maxJacobian) {
                    m.maxJacobian = jac;
                    maxAt = here;
                    maxPoint = p.x;
                }
                m.volume += weight[0][i] * weight[1][j] * weight[2][k] * jac;
            }
    const bool positive = m.volume >= 0.0;
    m.weakestParameters = positive ? minAt : maxAt;
    m.weakestPoint = positive ? minPoint : maxPoint;
    m.volume = std::abs(m.volume);
    return m;
}

void writeNurbsVolumeJson(const NurbsVolume& vol, std::ostream& out)
{
    checkVolume(vol);
    out << std::setprecision(17) << "{\"degrees\":[" << vol.degree[0] << "," << vol.degree[1] << "," << vol.degree[2] << "],\"knots\":[";
    for (int k = 0; k < 3; ++k) {
        out << (k ? ",[" : "[");
        for (std::size_t i = 0; i < vol.knots[k].size(); ++i) out << (i ? "," : "") << vol.knots[k][i];
        out << "]";
    }
    out << "],\"counts\":[" << vol.count[0] << "," << vol.count[1] << "," << vol.count[2] << "],\"poles\":[";
    for (std::size_t i = 0; i < vol.poles.size(); ++i)
        out << (i ? "," : "") << "[" << vol.poles[i].x << "," << vol.poles[i].y << "," << vol.poles[i].z << "," << vol.weights[i] << "]";
    out << "]}\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "writeNurbsVolumeJson: the stream could not be written");
}

void writeNurbsVolumeVtk(const NurbsVolume& vol, std::ostream& out, int samples)
{
    checkVolume(vol);
    if (samples < 1 || samples > 64) throw Error(ErrorCode::InvalidArgument, "writeNurbsVolumeVtk: 1 to 64 samples per span");
    // The sample parameters along each direction: every span cut into `samples` (w: at least 1).
    std::array<std::vector<double>, 3> at;
    for (int c = 0; c < 3; ++c) {
        const int per = c == 2 ? std::max(1, samples / 2) : samples;
        for (const auto& [lo, hi] : spansOf(vol.knots[c]))
            for (int k = 0; k < per; ++k) at[static_cast<std::size_t>(c)].push_back(lo + (hi - lo) * k / per);
        at[static_cast<std::size_t>(c)].push_back(vol.knots[c].back());
    }
    const std::size_t nu = at[0].size(), nv = at[1].size(), nw = at[2].size();
    const auto id = [&](std::size_t i, std::size_t j, std::size_t k) { return (i * nv + j) * nw + k; };
    out << std::setprecision(17) << "# vtk DataFile Version 3.0\ntowgeom NURBS ply solid\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS "
        << nu * nv * nw << " double\n";
    const std::array<std::vector<detail::BasisRow>, 3> rows{rowsAt(vol, 0, at[0]), rowsAt(vol, 1, at[1]), rowsAt(vol, 2, at[2])};
    std::vector<double> jac;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
            for (std::size_t k = 0; k < nw; ++k) {
                const VolumePoint p = combine(vol, rows[0][i], rows[1][j], rows[2][k]);
                out << p.x.x << " " << p.x.y << " " << p.x.z << "\n";
                jac.push_back(dot(p.d[0], cross(p.d[1], p.d[2])));
            }
    const std::size_t cells = (nu - 1) * (nv - 1) * (nw - 1);
    out << "CELLS " << cells << " " << 9 * cells << "\n";
    for (std::size_t i = 0; i + 1 < nu; ++i)
        for (std::size_t j = 0; j + 1 < nv; ++j)
            for (std::size_t k = 0; k + 1 < nw; ++k)
                out << "8 " << id(i, j, k) << " " << id(i + 1, j, k) << " " << id(i + 1, j + 1, k) << " " << id(i, j + 1, k) << " "
                    << id(i, j, k + 1) << " " << id(i + 1, j, k + 1) << " " << id(i + 1, j + 1, k + 1) << " " << id(i, j + 1, k + 1) << "\n";
    out << "CELL_TYPES " << cells << "\n";
    for (std::size_t c = 0; c < cells; ++c) out << "12\n";
    out << "POINT_DATA " << jac.size() << "\nSCALARS jacobian double 1\nLOOKUP_TABLE default\n";
    for (double j : jac) out << j << "\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "writeNurbsVolumeVtk: the stream could not be written");
}

TOWGEOM_END_NAMESPACE
