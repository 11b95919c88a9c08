#include "trimmed_face_family.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Circle.hxx>
#include <Geom2d_Ellipse.hxx>
#include <Geom_BSplineSurface.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax22d.hxx>
#include <gp_Circ2d.hxx>
#include <gp_Elips2d.hxx>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace towgeom::testing {

namespace {

TopoDS_Wire wireOn(const Handle(Geom2d_Curve)& c, const Handle(Geom_Surface)& s)
{
    TopoDS_Edge e = BRepBuilderAPI_MakeEdge(c, s).Edge();
    BRepLib::BuildCurves3d(e, 1e-9);
    return BRepBuilderAPI_MakeWire(e).Wire();
}

}  // namespace

RandomTrimmedPatch writeRandomTrimmedPatch(const std::string& path, unsigned seed, bool hole)
{
    std::mt19937 random(seed);
    const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
    const int nu = 6, nv = 5;
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) poles(i, j) = gp_Pnt(4.0 * (i - 1) / (nu - 1), 3.0 * (j - 1) / (nv - 1), uniform(-0.4, 0.4));
    TColStd_Array1OfReal uk(1, 4), vk(1, 3);
    TColStd_Array1OfInteger um(1, 4), vm(1, 3);
    for (int k = 1; k <= 4; ++k) uk(k) = (k - 1) / 3.0, um(k) = k == 1 || k == 4 ? 4 : 1;
    for (int k = 1; k <= 3; ++k) vk(k) = (k - 1) / 2.0, vm(k) = k == 1 || k == 3 ? 4 : 1;
    const Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
    // The ellipse inside the unit square with a margin of 0.03 all round.
    const double a = uniform(0.25, 0.45), b = uniform(0.18, 0.32), turn = uniform(0.0, M_PI);
    const double reach = std::max(a, b), narrow = std::min(a, b);
    const double cu = uniform(0.03 + reach, 0.97 - reach), cv = uniform(0.03 + reach, 0.97 - reach);
    const gp_Ax22d axes(gp_Pnt2d(cu, cv), gp_Dir2d(std::cos(turn), std::sin(turn)), gp_Dir2d(-std::sin(turn), std::cos(turn)));
    BRepBuilderAPI_MakeFace make(surface, wireOn(new Geom2d_Ellipse(gp_Elips2d(axes, a, b)), surface), true);
    RandomTrimmedPatch out;
    gp_Pnt2d at(cu, cv);
    if (hole) {
        const double r = uniform(0.005, 0.06), t = uniform(0.0, 2.0 * M_PI), away = uniform(0.0, narrow - r - 0.04);
        const gp_Pnt2d centre(cu + away * std::cos(t), cv + away * std::sin(t));
        TopoDS_Wire w = wireOn(new Geom2d_Circle(gp_Circ2d(gp_Ax2d(centre, gp_Dir2d(1.0, 0.0)), r)), surface);
        w.Reverse();  // clockwise: a hole
        make.Add(w);
        // A point on the face beside the hole, towards the ellipse's centre or away from it.
        const double d = r + 0.5 * (narrow - r - away);
        at = away > 1e-3 ? gp_Pnt2d(centre.X() - d * std::cos(t), centre.Y() - d * std::sin(t)) : gp_Pnt2d(centre.X() + d, centre.Y());
        out.hole = true;
    }
    TopoDS_Face face = make.Face();
    BRepLib::BuildCurves3d(face, 1e-9);
    if (!BRepCheck_Analyzer(face).IsValid()) throw std::runtime_error("random trimmed patch " + std::to_string(seed) + " is not valid");
    const gp_Pnt p = surface->Value(at.X(), at.Y());
    out.inside = {p.X(), p.Y(), p.Z()};
    STEPControl_Writer writer;
    if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write STEP " + path);
    return out;
}

struct FaceOracle::Data {
    TopoDS_Face face;
    double area = 0.0, size = 0.0;
};

FaceOracle::FaceOracle(const std::string& stepPath)
{
    STEPControl_Reader reader;
    if (reader.ReadFile(stepPath.c_str()) != IFSelect_RetDone || reader.TransferRoots() == 0) throw std::runtime_error("cannot read STEP " + stepPath);
    TopExp_Explorer x(reader.OneShape(), TopAbs_FACE);
    if (!x.More()) throw std::runtime_error("no face in " + stepPath);
    auto d = std::make_shared<Data>();
    d->face = TopoDS::Face(x.Current());
    GProp_GProps props;
    BRepGProp::SurfaceProperties(d->face, props, 1e-9);
    d->area = props.Mass();
    Bnd_Box box;
    BRepBndLib::Add(d->face, box);
    d->size = std::sqrt(box.SquareExtent());
    data_ = d;
}

namespace {

double distanceTo(const TopoDS_Shape& shape, const Point3& p)
{
    BRepExtrema_DistShapeShape d(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Vertex(), shape);
    if (!d.IsDone()) throw std::runtime_error("BRepExtrema failed");
    return d.Value();
}

}  // namespace

double FaceOracle::toFace(const Point3& p) const { return distanceTo(data_->face, p); }

double FaceOracle::toBoundary(const Point3& p) const
{
    double best = 1e300;
    for (TopExp_Explorer x(data_->face, TopAbs_WIRE); x.More(); x.Next()) best = std::min(best, distanceTo(x.Current(), p));
    return best;
}

double FaceOracle::area() const { return data_->area; }

double FaceOracle::edgeTolerance() const
{
    double largest = 0.0;
    for (TopExp_Explorer x(data_->face, TopAbs_EDGE); x.More(); x.Next()) largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Edge(x.Current())));
    return largest;
}
double FaceOracle::size() const { return data_->size; }

}  // namespace towgeom::testing
