#include "brep/cell_clip.hpp"

#include <BOPAlgo_PaveFiller.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <array>
#include <cmath>

#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

/// BRepGProp's relative precision for the cut-off parts (their faces have no holes: quick).
constexpr double kMeasureEps = 1e-7;

/// Whether @p face is planar and lies in one of @p cell's face planes (within @p tolerance).
bool onCellPlane(const TopoDS_Face& face, const Cell& cell, double tolerance)
{
    const BRepAdaptor_Surface s(face, Standard_False);
    if (s.GetType() != GeomAbs_Plane) return false;
    const gp_Pln plane = s.Plane();
    const gp_Dir n = plane.Axis().Direction();
    const gp_Pnt o = plane.Location();
    const std::array<double, 3> lo{cell.min.x, cell.min.y, cell.min.z}, hi{cell.max.x, cell.max.y, cell.max.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(std::abs(n.Coord(axis + 1)) - 1.0) > 1e-12) continue;
        const double at = o.Coord(axis + 1);
        if (std::abs(at - lo[static_cast<std::size_t>(axis)]) <= tolerance || std::abs(at - hi[static_cast<std::size_t>(axis)]) <= tolerance)
            return true;
    }
    return false;
}

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

        const double size = std::max({cell.max.x - cell.min.x, cell.max.y - cell.min.y, cell.max.z - cell.min.z});
        std::size_t pieces = 0;
        for (TopExp_Explorer x(common.Shape(), TopAbs_SOLID); x.More(); x.Next(), ++pieces) out.inside = TopoDS::Solid(x.Current());
        if (pieces > 1)
            throw Error(ErrorCode::Unsupported, "tow '" + tow + "' is cut into " + std::to_string(pieces) +
                                                    " solids by the cell's box: not built as a trimmed B-rep");
        if (out.inside)
            for (TopExp_Explorer x(*out.inside, TopAbs_FACE); x.More(); x.Next()) {
                const TopoDS_Face f = TopoDS::Face(x.Current());
                if (!onCellPlane(f, cell, 1e-9 * size)) continue;
                GProp_GProps a;
                BRepGProp::SurfaceProperties(f, a, kMeasureEps);
                out.cutArea += a.Mass();
            }
        if (!out.inside) return out;  // wholly outside: nothing to measure
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

}  // namespace detail
TOWGEOM_END_NAMESPACE
