// A tool surface from STEP or IGES (OpenCASCADE's readers), converted exactly to a clamped
// B-spline over the face's parameter box.
#include "towgeom/placement_surface.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IGESControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "brep/quiet_messenger.hpp"
#include "placement/nurbs_geometry.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

std::string lowerExtension(const std::string& path)
{
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

TopoDS_Shape readShape(const std::string& path)
{
    const std::string ext = lowerExtension(path);
    const bool step = ext == ".step" || ext == ".stp", iges = ext == ".iges" || ext == ".igs";
    if (!step && !iges)
        throw Error(ErrorCode::InvalidArgument, "a placement surface is read from STEP (.step, .stp) or IGES (.iges, .igs), not '" + ext + "'",
                    path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(ErrorCode::FileNotFound, "no such file", path);
    if (!std::ifstream(path)) throw Error(ErrorCode::FileUnreadable, "cannot be opened for reading", path);
    const std::lock_guard<std::mutex> lock(detail::dataExchangeMutex());
    const detail::QuietMessenger quiet;
    if (step) {
        STEPControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw Error(ErrorCode::FileUnreadable, "not a STEP file OpenCASCADE can read", path);
        if (reader.TransferRoots() == 0) throw Error(ErrorCode::FileUnreadable, "the STEP file holds no shape", path);
        return reader.OneShape();
    }
    IGESControl_Reader reader;
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw Error(ErrorCode::FileUnreadable, "not an IGES file OpenCASCADE can read", path);
    if (reader.TransferRoots() == 0) throw Error(ErrorCode::FileUnreadable, "the IGES file holds no shape", path);
    return reader.OneShape();
}

}  // namespace

PlacementSurface readPlacementSurface(const std::string& path, std::size_t which)
{
    try {
        const TopoDS_Shape shape = readShape(path);
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next()) faces.push_back(TopoDS::Face(x.Current()));
        if (which >= faces.size())
            throw Error(ErrorCode::InvalidArgument, "face " + std::to_string(which) + " asked for, the file has " + std::to_string(faces.size()) +
                                                        " face(s) (0-based)", path);
        const TopoDS_Face& face = faces[which];
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        // The face's box within the surface's range where the surface is not periodic (a face's
        // curves may run past it by a tolerance); a periodic direction is moved into range by the
        // trimming itself.
        double su0, su1, sv0, sv1;
        surface->Bounds(su0, su1, sv0, sv1);
        if (!surface->IsUPeriodic()) u0 = std::max(u0, su0), u1 = std::min(u1, su1);
        if (!surface->IsVPeriodic()) v0 = std::max(v0, sv0), v1 = std::min(v1, sv1);
        Handle(Geom_BSplineSurface) b = GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1));
        if (b.IsNull()) throw Error(ErrorCode::InvalidArgument, "face " + std::to_string(which) + "'s surface has no B-spline form", path);
        b = Handle(Geom_BSplineSurface)::DownCast(b->Copy());
        // Clamped over its own range (the face's box, possibly moved by whole periods): a periodic
        // conversion (a full cylinder's u) is opened, then cut back to that range, which gives its
        // ends full multiplicity.
        double bu0, bu1, bv0, bv1;
        b->Bounds(bu0, bu1, bv0, bv1);
        if (b->IsUPeriodic()) b->SetUNotPeriodic();
        if (b->IsVPeriodic()) b->SetVNotPeriodic();
        b->Segment(bu0, bu1, bv0, bv1);
        if (face.Orientation() == TopAbs_REVERSED) b->UReverse();  // the normal out of the face's material
        PlacementSurface p;
        p.surface = detail::nurbsSurface(b);
        p.faceCount = faces.size();
        p.face = which;
        return p;
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed reading the placement surface: ") + e.GetMessageString(), path);
    }
}

TOWGEOM_END_NAMESPACE
