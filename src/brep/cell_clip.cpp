#include "brep/cell_clip.hpp"

#include <BOPAlgo_PaveFiller.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListIteratorOfListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

/// BRepGProp's relative precision for the cut-off parts (their faces have no holes: quick); the
/// clipped volume, the whole solid's less theirs, is within 1e-9 of their volume.
constexpr double kMeasureEps = 1e-9;

}  // namespace

ClippedSolid clipSolidToCell(const TopoDS_Solid& solid, const Cell& cell, const std::string& tow)
{
    ClippedSolid out;
    try {
        const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(cell.min.x, cell.min.y, cell.min.z),
                                                     gp_Pnt(cell.max.x, cell.max.y, cell.max.z)).Solid();
        TopTools_ListOfShape arguments;
        arguments.Append(solid);
        arguments.Append(box);
        BOPAlgo_PaveFiller intersection;
        intersection.SetArguments(arguments);
        // Destructive (OCCT's default): a tolerance the intersection raises is raised on the
        // shared edge itself, not on a copy, so the faces two tows share stay one face.
        intersection.Perform();
        if (intersection.HasErrors())
            throw Error(ErrorCode::Internal, "tow '" + tow + "': OpenCASCADE could not intersect its solid with the cell's box");
        BRepAlgoAPI_Common common(solid, box, intersection);
        BRepAlgoAPI_Cut cut(solid, box, intersection);
        if (!common.IsDone() || common.HasErrors() || !cut.IsDone() || cut.HasErrors())
            throw Error(ErrorCode::Internal, "tow '" + tow + "': OpenCASCADE could not clip its solid to the cell's box");

        std::size_t pieces = 0;
        for (TopExp_Explorer x(common.Shape(), TopAbs_SOLID); x.More(); x.Next(), ++pieces) out.inside = TopoDS::Solid(x.Current());
        if (pieces > 1)
            throw Error(ErrorCode::Unsupported, "tow '" + tow + "' is cut into " + std::to_string(pieces) +
                                                    " solids by the cell's box: not built as a trimmed B-rep");
        if (!out.inside) return out;  // wholly outside: nothing to measure
        // The cut faces: what the boolean made of the box's faces (its history), not whatever
        // lies in a box plane (a tow's own end cap may).
        TopTools_IndexedMapOfShape cutFaces;
        for (TopExp_Explorer x(box, TopAbs_FACE); x.More(); x.Next())
            for (TopTools_ListIteratorOfListOfShape m(common.Modified(x.Current())); m.More(); m.Next()) cutFaces.Add(m.Value());
        for (TopExp_Explorer x(*out.inside, TopAbs_FACE); x.More(); x.Next()) {
            if (!cutFaces.Contains(x.Current())) continue;
            GProp_GProps a;
            BRepGProp::SurfaceProperties(x.Current(), a, kMeasureEps);
            out.cutArea += a.Mass();
            ++out.cutFaces;
        }
        for (TopExp_Explorer x(cut.Shape(), TopAbs_SOLID); x.More(); x.Next()) {
            GProp_GProps v, a;
            BRepGProp::VolumeProperties(x.Current(), v, kMeasureEps);
            BRepGProp::SurfaceProperties(x.Current(), a, kMeasureEps);
            out.outsideVolume += std::abs(v.Mass());
            out.outsideArea += a.Mass();
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, "tow '" + tow + "': OpenCASCADE failed clipping its solid to the cell: " + e.GetMessageString());
    }
    return out;
}

namespace {

/// The box minus @p tools by OpenCASCADE's boolean cut with the gluing option @p glue; empty
/// when the boolean fails or its result is not valid (BRepCheck_Analyzer).
std::vector<TopoDS_Solid> cutBox(const TopoDS_Shape& box, const TopTools_ListOfShape& tools, BOPAlgo_GlueEnum glue,
                                 BRepAlgoAPI_Cut& cut)
{
    TopTools_ListOfShape arguments;
    arguments.Append(box);
    cut.SetArguments(arguments);
    cut.SetTools(tools);
    cut.SetGlue(glue);
    cut.SetRunParallel(Standard_True);
    cut.Build();
    std::vector<TopoDS_Solid> pieces;
    if (!cut.IsDone() || cut.HasErrors()) return pieces;
    for (TopExp_Explorer x(cut.Shape(), TopAbs_SOLID); x.More(); x.Next()) {
        if (!BRepCheck_Analyzer(x.Current()).IsValid()) return {};
        pieces.push_back(TopoDS::Solid(x.Current()));
    }
    return pieces;
}

}  // namespace

MatrixCut cutMatrix(const std::vector<TopoDS_Solid>& tows, const Cell& cell)
{
    MatrixCut out;
    try {
        const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(cell.min.x, cell.min.y, cell.min.z),
                                                     gp_Pnt(cell.max.x, cell.max.y, cell.max.z)).Solid();
        if (tows.empty()) {  // no tow inside: the box itself
            out.pieces.push_back(TopoDS::Solid(box));
            out.faces = out.cellFaces = 6;
            return out;
        }
        TopTools_ListOfShape tools;
        for (const TopoDS_Solid& t : tows) tools.Append(t);
        // The clipped tows lie inside the box, their cut faces on its faces: the box's faces and
        // theirs overlap without crossing, the case OpenCASCADE's gluing option is for (the
        // 4x4 twill cell: 0.6 s instead of 15 s). Its result is checked; the full boolean is
        // the fallback.
        BRepAlgoAPI_Cut glued, full;
        BRepAlgoAPI_Cut* cut = &glued;
        out.pieces = cutBox(box, tools, BOPAlgo_GlueShift, glued);
        if (out.pieces.empty()) {
            cut = &full;
            out.pieces = cutBox(box, tools, BOPAlgo_GlueOff, full);
        }
        if (out.pieces.empty()) {
            out.failure = "OpenCASCADE's boolean cut of the box by the tows failed or gave an invalid solid";
            return out;
        }
        TopTools_IndexedMapOfShape towFaces, boxFaces;
        for (const TopoDS_Solid& t : tows)
            for (TopExp_Explorer x(t, TopAbs_FACE); x.More(); x.Next()) towFaces.Add(x.Current());
        for (TopExp_Explorer x(box, TopAbs_FACE); x.More(); x.Next()) {
            boxFaces.Add(x.Current());  // kept as it is where no tow reaches it
            for (TopTools_ListIteratorOfListOfShape m(cut->Modified(x.Current())); m.More(); m.Next()) boxFaces.Add(m.Value());
        }
        for (const TopoDS_Solid& piece : out.pieces)
            for (TopExp_Explorer x(piece, TopAbs_FACE); x.More(); x.Next()) {
                ++out.faces;
                if (towFaces.Contains(x.Current())) ++out.sharedFaces;
                if (boxFaces.Contains(x.Current())) ++out.cellFaces;
            }
    } catch (const Standard_Failure& e) {
        out.pieces.clear();
        out.failure = std::string("OpenCASCADE failed cutting the box by the tows: ") + e.GetMessageString();
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
