#include "occt_reference.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <gp_Circ.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <TopTools_ListOfShape.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <gp_Ax3.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <IGESControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_ChildIterator.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <math.hxx>
#include <math_Vector.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Compound.hxx>

#include <towgeom/bezier_extraction.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace towgeom::testing {

namespace {

ReadShapes describe(const TopoDS_Shape& shape, const std::vector<std::pair<TopoDS_Shape, std::string>>& names, bool volumes)
{
    ReadShapes r;
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    std::vector<TopTools_IndexedMapOfShape> faces(solids.size());
    for (std::size_t k = 0; k < solids.size(); ++k) {
        ReadSolid s;
        for (const auto& [named, name] : names)
            if (named.IsSame(solids[k])) s.name = name;
        s.valid = BRepCheck_Analyzer(solids[k]).IsValid();
        if (volumes) {
            GProp_GProps p;
            BRepGProp::VolumeProperties(solids[k], p, 1e-7, Standard_True);
            s.volume = p.Mass();
        }
        TopExp::MapShapes(solids[k], TopAbs_FACE, faces[k]);
        s.faces = static_cast<std::size_t>(faces[k].Extent());
        r.solids.push_back(s);
    }
    for (std::size_t i = 0; i < solids.size(); ++i)
        for (std::size_t j = i + 1; j < solids.size(); ++j) {
            std::size_t n = 0;
            for (int k = 1; k <= faces[i].Extent(); ++k) n += faces[j].Contains(faces[i](k)) ? 1 : 0;
            if (n > 0) r.sharedFaces.push_back({{i, j}, n});
        }
    return r;
}

TopoDS_Shape brepShape(const std::string& path)
{
    TopoDS_Shape shape;
    BRep_Builder b;
    if (!BRepTools::Read(shape, path.c_str(), b)) throw std::runtime_error("cannot read BREP " + path);
    return shape;
}

}  // namespace

ReadShapes readStep(const std::string& path)
{
    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;  // first: it registers the parameter set below
    Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
    reader.SetNameMode(Standard_True);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || !reader.Transfer(doc))
        throw std::runtime_error("cannot read STEP " + path);
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence free;
    tool->GetFreeShapes(free);
    if (free.Length() != 1) throw std::runtime_error("STEP " + path + ": not one top-level shape");
    std::vector<std::pair<TopoDS_Shape, std::string>> names;
    for (TDF_ChildIterator it(free.Value(1), Standard_True); it.More(); it.Next()) {
        Handle(TDataStd_Name) n;
        if (!it.Value().FindAttribute(TDataStd_Name::GetID(), n)) continue;
        names.push_back({tool->GetShape(it.Value()), TCollection_AsciiString(n->Get()).ToCString()});
    }
    const ReadShapes r = describe(tool->GetShape(free.Value(1)), names, true);
    XCAFApp_Application::GetApplication()->Close(doc);
    return r;
}

std::vector<ReadEdge> readStepEdges(const std::string& path, int samples)
{
    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader reader;
    Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
    reader.SetNameMode(Standard_True);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone || !reader.Transfer(doc)) throw std::runtime_error("cannot read STEP " + path);
    const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    TDF_LabelSequence free;
    tool->GetFreeShapes(free);
    std::vector<ReadEdge> out;
    TDF_LabelSequence labels;  // the free shapes and every label under them
    for (int f = 1; f <= free.Length(); ++f) {
        labels.Append(free.Value(f));
        for (TDF_ChildIterator it(free.Value(f), Standard_True); it.More(); it.Next()) labels.Append(it.Value());
    }
    for (int l = 1; l <= labels.Length(); ++l) {
        {
            Handle(TDataStd_Name) n;
            // A named curve set (GEOMETRIC_CURVE_SET) comes back as a shape holding its edge.
            const TopoDS_Shape shape = tool->GetShape(labels.Value(l));
            if (shape.IsNull() || !labels.Value(l).FindAttribute(TDataStd_Name::GetID(), n)) continue;
            TopExp_Explorer x(shape, TopAbs_EDGE);
            if (!x.More()) continue;
            const TopoDS_Edge edge = TopoDS::Edge(x.Current());
            x.Next();
            if (x.More()) continue;  // not one edge
            ReadEdge e;
            e.name = TCollection_AsciiString(n->Get()).ToCString();
            double first = 0.0, last = 0.0;
            const Handle(Geom_Curve) c = BRep_Tool::Curve(edge, first, last);
            if (c.IsNull()) throw std::runtime_error("STEP " + path + ": edge " + e.name + " has no 3D curve");
            for (int k = 0; k < samples; ++k) {
                const gp_Pnt p = c->Value(first + (last - first) * k / (samples - 1));
                e.points.push_back({p.X(), p.Y(), p.Z()});
            }
            out.push_back(e);
        }
    }
    XCAFApp_Application::GetApplication()->Close(doc);
    return out;
}

ReadShapes readBrep(const std::string& path, bool volumes) { return describe(brepShape(path), {}, volumes); }

void writeCylinderFace(const std::string& path, double radius, double height, double fromAngle, double toAngle)
{
    TopoDS_Shape lateral;
    if (fromAngle < toAngle) {
        lateral = BRepBuilderAPI_MakeFace(new Geom_CylindricalSurface(gp_Ax3(), radius), fromAngle, toAngle, 0.0, height, 1e-7).Face();
    } else {
        const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(radius, height).Shape();
        for (TopExp_Explorer x(cylinder, TopAbs_FACE); x.More(); x.Next())
            if (!Handle(Geom_CylindricalSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(x.Current()))).IsNull()) lateral = x.Current();
    }
    if (path.size() > 4 && path.substr(path.size() - 4) == ".igs") {
        IGESControl_Writer writer("MM", 1);
        writer.AddShape(lateral);
        writer.ComputeModel();
        if (!writer.Write(path.c_str())) throw std::runtime_error("cannot write IGES " + path);
        return;
    }
    STEPControl_Writer writer;
    if (writer.Transfer(lateral, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write STEP " + path);
}

void writeSphereFace(const std::string& path, double radius, double fromLatitude, double toLatitude)
{
    const TopoDS_Face face =
        BRepBuilderAPI_MakeFace(new Geom_SphericalSurface(gp_Ax3(), radius), 0.0, 2.0 * M_PI, fromLatitude, toLatitude, 1e-7).Face();
    STEPControl_Writer writer;
    if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write STEP " + path);
}

void writeTorusFace(const std::string& path, double major, double minor)
{
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(new Geom_ToroidalSurface(gp_Ax3(), major, minor), 1e-7).Face();
    STEPControl_Writer writer;
    if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write STEP " + path);
}

namespace {

void writeFaceStep(const TopoDS_Shape& face, const std::string& path)
{
    STEPControl_Writer writer;
    if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write STEP " + path);
}

}  // namespace

void writeDiskFace(const std::string& path, double radius, double cutX, bool reversed, double holeX, double holeRadius)
{
    const gp_Circ circle(gp_Ax2(), radius);
    TopoDS_Wire wire;
    if (cutX < radius) {
        const double a = std::acos(cutX / radius), h = radius * std::sin(a);
        const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(circle, a, 2.0 * M_PI - a).Edge();
        const TopoDS_Edge line = BRepBuilderAPI_MakeEdge(gp_Pnt(cutX, -h, 0.0), gp_Pnt(cutX, h, 0.0)).Edge();
        wire = BRepBuilderAPI_MakeWire(arc, line).Wire();
    } else {
        wire = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    }
    BRepBuilderAPI_MakeFace make(wire, true);
    if (holeRadius > 0.0) {
        TopoDS_Wire hole = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(holeX, 0.0, 0.0), gp::DZ()), holeRadius)).Edge()).Wire();
        hole.Reverse();  // clockwise seen from +z: a hole
        make.Add(hole);
    }
    TopoDS_Face face = make.Face();
    if (reversed) face.Reverse();
    writeFaceStep(face, path);
}

namespace {

/// The lateral face of @p solid (the one on a cylindrical or conical surface).
TopoDS_Face lateralFace(const TopoDS_Shape& solid)
{
    for (TopExp_Explorer x(solid, TopAbs_FACE); x.More(); x.Next()) {
        const TopoDS_Face& f = TopoDS::Face(x.Current());
        const GeomAdaptor_Surface a(BRep_Tool::Surface(f));
        if (a.GetType() == GeomAbs_Cylinder || a.GetType() == GeomAbs_Cone) return f;
    }
    throw std::runtime_error("no lateral face");
}

}  // namespace

void writeCylinderConeShell(const std::string& path, double radius, double height, double topRadius, double coneHeight)
{
    const TopoDS_Face cylinder = lateralFace(BRepPrimAPI_MakeCylinder(radius, height).Shape());
    const gp_Ax2 above(gp_Pnt(0.0, 0.0, height), gp::DZ());
    const TopoDS_Face cone = lateralFace(BRepPrimAPI_MakeCone(above, radius, topRadius, coneHeight).Shape());
    BRepBuilderAPI_Sewing sewing(1e-6);
    sewing.Add(cylinder);
    sewing.Add(cone);
    sewing.Perform();
    writeFaceStep(sewing.SewedShape(), path);
}

namespace {

/// The face of the bilinear B-spline through the corners @p a, @p b (v = 0, u = 0 and 1) and
/// @p c, @p d (v = 1).
TopoDS_Face bilinearFace(const gp_Pnt& a, const gp_Pnt& b, const gp_Pnt& c, const gp_Pnt& d)
{
    TColgp_Array2OfPnt poles(1, 2, 1, 2);
    poles(1, 1) = a, poles(2, 1) = b, poles(1, 2) = c, poles(2, 2) = d;
    TColStd_Array1OfReal knots(1, 2);
    TColStd_Array1OfInteger mults(1, 2);
    knots(1) = 0.0, knots(2) = 1.0, mults(1) = mults(2) = 2;
    return BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, knots, knots, mults, mults, 1, 1), 1e-7).Face();
}

}  // namespace

void writeFoldedSheet(const std::string& path, double fold)
{
    const double c = std::cos(fold), s = std::sin(fold);
    const TopoDS_Face flat = bilinearFace(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0), gp_Pnt(0, 2, 0), gp_Pnt(4, 2, 0));
    const TopoDS_Face turned = bilinearFace(gp_Pnt(0, 2, 0), gp_Pnt(4, 2, 0), gp_Pnt(0.5, 2 + 2 * c, 2 * s), gp_Pnt(3.5, 2 + 2 * c, 2 * s));
    BRepBuilderAPI_Sewing sewing(1e-6);
    sewing.Add(flat);
    sewing.Add(turned);
    sewing.Perform();
    writeFaceStep(sewing.SewedShape(), path);
}

void writeHoledCylinderFace(const std::string& path, double radius, double height, double holeRadius)
{
    const TopoDS_Shape body = BRepPrimAPI_MakeCylinder(radius, height).Shape();
    const gp_Ax2 across(gp_Pnt(0.0, -2.0 * radius, 0.5 * height), gp_Dir(0.0, 1.0, 0.0));
    const TopoDS_Shape drill = BRepPrimAPI_MakeCylinder(across, holeRadius, 4.0 * radius).Shape();
    BRepAlgoAPI_Cut cut(body, drill);
    if (!cut.IsDone()) throw std::runtime_error("the cylinder's holes could not be cut");
    for (TopExp_Explorer x(cut.Shape(), TopAbs_FACE); x.More(); x.Next()) {
        const TopoDS_Face& f = TopoDS::Face(x.Current());
        const Handle(Geom_CylindricalSurface) c = Handle(Geom_CylindricalSurface)::DownCast(BRep_Tool::Surface(f));
        if (!c.IsNull() && std::abs(c->Radius() - radius) < 1e-9 * radius && c->Axis().Direction().IsParallel(gp::DZ(), 1e-12)) {
            writeFaceStep(f, path);
            return;
        }
    }
    throw std::runtime_error("the holed cylinder's lateral face was not found");
}

namespace {

/// A flat knot vector as OCCT's distinct knots and multiplicities.
void knotsAndMultiplicities(const std::vector<double>& flat, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults)
{
    std::vector<double> k;
    std::vector<int> m;
    for (const double x : flat)
        if (!k.empty() && x == k.back())
            ++m.back();
        else {
            k.push_back(x);
            m.push_back(1);
        }
    knots.Resize(1, static_cast<int>(k.size()), false);
    mults.Resize(1, static_cast<int>(k.size()), false);
    for (std::size_t i = 0; i < k.size(); ++i) {
        knots(static_cast<int>(i) + 1) = k[i];
        mults(static_cast<int>(i) + 1) = m[i];
    }
}

}  // namespace

std::vector<WholeTowSolid> writeWholeTowSolids(const std::vector<TowSurface>& tows, const std::string& path)
{
    std::vector<WholeTowSolid> out;
    BRep_Builder b;
    TopoDS_Compound all;
    b.MakeCompound(all);
    for (const TowSurface& tow : tows) {
        const BezierSurface z = extractBezier(tow);
        const int p = static_cast<int>(z.uDegree), q = static_cast<int>(z.vDegree);
        const int nu = static_cast<int>(z.uFunctions), nvPeriod = static_cast<int>(z.vFunctions);
        const int nv = static_cast<int>(z.vKnots.size()) - q - 1;  // the unrolled functions
        if (static_cast<int>(z.uKnots.size()) != nu + p + 1 || nv < nvPeriod || z.controlPoints.size() != z.uFunctions * z.vFunctions)
            throw std::runtime_error("writeWholeTowSolids: tow '" + tow.name() + "': B-spline data of unexpected sizes");
        TColgp_Array2OfPnt poles(1, nu, 1, nv);
        for (int i = 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                const Point3& c = z.controlPoints[static_cast<std::size_t>(i * nvPeriod + j % nvPeriod)];
                poles(i + 1, j + 1) = gp_Pnt(c.x, c.y, c.z);
            }
        TColStd_Array1OfReal uk(1, 1), vk(1, 1);
        TColStd_Array1OfInteger um(1, 1), vm(1, 1);
        knotsAndMultiplicities(z.uKnots, uk, um);
        knotsAndMultiplicities(z.vKnots, vk, vm);
        Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(poles, uk, vk, um, vm, p, q, Standard_False, Standard_False);
        // One period in v, clamped at its ends (exact: knot insertion).
        const double u0 = z.uKnots.front(), u1 = z.uKnots.back();
        const double v0 = z.vKnots[static_cast<std::size_t>(q)], v1 = z.vKnots[static_cast<std::size_t>(q + nvPeriod)];
        s->Segment(u0, u1, v0, v1);
        WholeTowSolid w;
        for (int i = 0; i <= 19; ++i)
            for (int j = 0; j < 20; ++j) {
                const double u = u0 + (u1 - u0) * i / 19.0, v = v0 + (v1 - v0) * (j + 0.5) / 20.0;
                const Point3 a = tow.point(u, v);
                w.surfaceError = std::max(w.surfaceError, s->Value(u, v).Distance(gp_Pnt(a.x, a.y, a.z)));
            }
        const double tolerance = 1e-7 * tow.towSize();
        BRepBuilderAPI_Sewing sewing(tolerance);
        sewing.Add(BRepBuilderAPI_MakeFace(s, u0, u1, v0, v1, tolerance).Face());
        for (const double u : {u0, u1}) {
            const TopoDS_Wire rim = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(s->UIso(u)).Edge()).Wire();
            BRepBuilderAPI_MakeFace cap(rim, Standard_True);
            if (!cap.IsDone()) throw std::runtime_error("writeWholeTowSolids: tow '" + tow.name() + "': an end is not planar");
            sewing.Add(cap.Face());
        }
        sewing.Perform();
        const TopoDS_Shape sewn = sewing.SewedShape();
        TopExp_Explorer shells(sewn, TopAbs_SHELL);
        if (!shells.More() || sewing.NbFreeEdges() != 0)
            throw std::runtime_error("writeWholeTowSolids: tow '" + tow.name() + "': not sewn into one closed shell");
        TopoDS_Solid solid = BRepBuilderAPI_MakeSolid(TopoDS::Shell(shells.Current())).Solid();
        BRepLib::OrientClosedSolid(solid);
        w.valid = BRepCheck_Analyzer(solid).IsValid();
        GProp_GProps g;
        BRepGProp::VolumeProperties(solid, g, 1e-5, Standard_True);  // 1e-7 takes 0.2 s a tow
        w.volume = g.Mass();
        b.Add(all, solid);
        out.push_back(w);
    }
    if (!BRepTools::Write(all, path.c_str())) throw std::runtime_error("cannot write BREP " + path);
    return out;
}

double commonVolume(const std::string& path, std::size_t i, std::size_t j)
{
    const TopoDS_Shape shape = brepShape(path);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    BRepAlgoAPI_Common common(solids.at(i), solids.at(j));
    if (!common.IsDone()) throw std::runtime_error("BRepAlgoAPI_Common failed");
    GProp_GProps p;
    BRepGProp::VolumeProperties(common.Shape(), p, 1e-7, Standard_True);
    return p.Mass();
}

double unionVolume(const std::string& path)
{
    const TopoDS_Shape shape = brepShape(path);
    TopTools_ListOfShape solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.Append(x.Current());
    if (solids.Extent() < 2) throw std::runtime_error("unionVolume: fewer than two solids");
    TopTools_ListOfShape first, rest = solids;
    first.Append(rest.First());
    rest.RemoveFirst();
    BRepAlgoAPI_Fuse fuse;
    fuse.SetArguments(first);
    fuse.SetTools(rest);
    fuse.Build();
    if (!fuse.IsDone() || fuse.HasErrors()) throw std::runtime_error("BRepAlgoAPI_Fuse failed");
    GProp_GProps p;
    BRepGProp::VolumeProperties(fuse.Shape(), p, 1e-7, Standard_True);
    return p.Mass();
}

double readBrepArea(const std::string& path, std::size_t i)
{
    const TopoDS_Shape shape = brepShape(path);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    GProp_GProps p;
    BRepGProp::SurfaceProperties(solids.at(i), p, 1e-7, Standard_True);
    return p.Mass();
}

double boxCommonVolume(const std::string& path, std::size_t i, const std::array<double, 3>& min, const std::array<double, 3>& max)
{
    const TopoDS_Shape shape = brepShape(path);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(min[0], min[1], min[2]), gp_Pnt(max[0], max[1], max[2])).Solid();
    BRepAlgoAPI_Common common(solids.at(i), box);
    if (!common.IsDone()) throw std::runtime_error("BRepAlgoAPI_Common failed");
    GProp_GProps p;
    BRepGProp::VolumeProperties(common.Shape(), p, 1e-7, Standard_True);
    return p.Mass();
}

double boxCommonVolume(const std::string& path, std::size_t i, std::size_t j, const std::array<double, 3>& min,
                       const std::array<double, 3>& max)
{
    const TopoDS_Shape shape = brepShape(path);
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer x(shape, TopAbs_SOLID); x.More(); x.Next()) solids.push_back(x.Current());
    BRepAlgoAPI_Common both(solids.at(i), solids.at(j));
    if (!both.IsDone()) throw std::runtime_error("BRepAlgoAPI_Common failed");
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(min[0], min[1], min[2]), gp_Pnt(max[0], max[1], max[2])).Solid();
    BRepAlgoAPI_Common inside(both.Shape(), box);
    if (!inside.IsDone()) throw std::runtime_error("BRepAlgoAPI_Common failed");
    GProp_GProps p;
    BRepGProp::VolumeProperties(inside.Shape(), p, 1e-7, Standard_True);
    return p.Mass();
}

std::vector<std::array<double, 2>> gaussLegendre01(int n)
{
    math_Vector points(1, n), weights(1, n);
    math::GaussPoints(n, points);
    math::GaussWeights(n, weights);
    std::vector<std::array<double, 2>> rule;
    for (int i = 1; i <= n; ++i) rule.push_back({0.5 * (points(i) + 1.0), 0.5 * weights(i)});
    return rule;
}

}  // namespace towgeom::testing
