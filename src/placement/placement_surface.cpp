// A tool surface from STEP or IGES (OpenCASCADE's readers), converted exactly to a clamped
// B-spline over the face's parameter box, found by index or by the name the file gives it.
#include "towgeom/placement_surface.hpp"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_IGESEntity.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TransferBRep.hxx>
#include <Transfer_Binder.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "brep/quiet_messenger.hpp"
#include "placement/face_join.hpp"
#include "placement/face_trim.hpp"
#include "placement/nurbs_geometry.hpp"
#include "placement/surface_grid.hpp"
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

/// A file's faces, in OpenCASCADE's exploration order, with their names in the file.
struct FileFaces {
    std::vector<TopoDS_Face> faces;
    std::vector<std::string> names;
};

/// @p text without blanks at either end.
std::string trimmed(const std::string& text)
{
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

/// An IGES entity's name: its Name property as written, or its short label (right-justified in
/// 8 columns: trimmed) with its subscript as "LABEL(n)", the subscript being what tells
/// entities of one label apart (a subscript 0 is the usual default: none).
std::string igesName(const Handle(IGESData_IGESEntity)& e)
{
    const std::string value = e->NameValue()->ToCString();
    if (e->HasShortLabel()) {
        const std::string label = e->ShortLabel()->ToCString();
        const bool hasSub = e->HasSubScriptNumber() && e->SubScriptNumber() != 0;  // 0: the usual default, no subscript
        const std::string sub = hasSub ? "(" + std::to_string(e->SubScriptNumber()) + ")" : "";
        const auto squeezed = [](std::string t) {
            t.erase(std::remove_if(t.begin(), t.end(), [](unsigned char c) { return std::isspace(c) != 0; }), t.end());
            return t;
        };
        const std::string raw = e->HasSubScriptNumber() ? "(" + std::to_string(e->SubScriptNumber()) + ")" : "";
        if (squeezed(value) == squeezed(label + raw)) return trimmed(label) + sub;  // no Name property
    }
    return trimmed(value);
}

/// The names the file gives the faces it made (STEP representation items and IGES entities
/// carry one), by the face's shared geometry (TShape: the same under any location, as in an
/// assembly): one pass over the transfer's map.
std::map<const TopoDS_TShape*, std::string> faceNames(const Handle(XSControl_WorkSession)& session)
{
    std::map<const TopoDS_TShape*, std::string> out;
    const Handle(Transfer_TransientProcess) process = session->TransferReader()->TransientProcess();
    if (process.IsNull()) return out;
    for (int i = 1; i <= process->NbMapped(); ++i) {
        const Handle(Standard_Transient)& entity = process->Mapped(i);
        std::string name;
        if (const auto item = Handle(StepRepr_RepresentationItem)::DownCast(entity); !item.IsNull()) {
            if (!item->Name().IsNull()) name = trimmed(item->Name()->ToCString());
        } else if (const auto e = Handle(IGESData_IGESEntity)::DownCast(entity); !e.IsNull() && e->HasName()) {
            name = igesName(e);
        }
        if (name.empty()) continue;
        const TopoDS_Shape shape = TransferBRep::ShapeResult(process->MapItem(i));
        if (shape.IsNull() || shape.ShapeType() != TopAbs_FACE) continue;
        out.emplace(shape.TShape().get(), name);
    }
    return out;
}

template <class Reader>
FileFaces facesOf(Reader& reader, const std::string& path, const char* kind)
{
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw Error(ErrorCode::FileUnreadable, std::string("not a ") + kind + " file OpenCASCADE can read", path);
    if (reader.TransferRoots() == 0) throw Error(ErrorCode::FileUnreadable, std::string("the ") + kind + " file holds no shape", path);
    FileFaces out;
    const std::map<const TopoDS_TShape*, std::string> names = faceNames(reader.WS());
    for (TopExp_Explorer x(reader.OneShape(), TopAbs_FACE); x.More(); x.Next()) {
        out.faces.push_back(TopoDS::Face(x.Current()));
        const auto it = names.find(out.faces.back().TShape().get());
        out.names.push_back(it == names.end() ? std::string() : it->second);
    }
    return out;
}

FileFaces readFaces(const std::string& path)
{
    const std::string ext = lowerExtension(path);
    const bool step = ext == ".step" || ext == ".stp", iges = ext == ".iges" || ext == ".igs";
    if (!step && !iges)
        throw Error(ErrorCode::InvalidArgument,
                    "a placement surface is read from STEP (.step, .stp), IGES (.iges, .igs) or a point grid (.grid), not '" + ext + "'", path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(ErrorCode::FileNotFound, "no such file", path);
    if (!std::ifstream(path)) throw Error(ErrorCode::FileUnreadable, "cannot be opened for reading", path);
    const std::lock_guard<std::mutex> lock(detail::dataExchangeMutex());
    const detail::QuietMessenger quiet;
    if (step) {
        STEPControl_Reader reader;
        return facesOf(reader, path, "STEP");
    }
    IGESControl_Reader reader;
    return facesOf(reader, path, "IGES");
}

/// Face @p which of @p faces as a placement surface.
PlacementSurface convertFace(const FileFaces& faces, std::size_t which, const std::string& path)
{
    const TopoDS_Face& face = faces.faces[which];
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
    Handle(Geom_BSplineSurface) b;
    try {
        b = GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1));
    } catch (const Standard_Failure&) {
        // A whole period to rounding from just off the period's start (a cone's face from
        // u = -4e-13): OpenCASCADE's conversion of a cone fails there. Tried again over the period
        // itself, from the multiple of it nearest the start; any other failure stands.
        const auto wholePeriod = [](double& a, double& c, double period) {
            if (std::abs(c - a - period) > 1e-9 * period) return false;
            a = period * std::round(a / period), c = a + period;
            return true;
        };
        const bool uWhole = surface->IsUPeriodic() && wholePeriod(u0, u1, surface->UPeriod());
        const bool vWhole = surface->IsVPeriodic() && wholePeriod(v0, v1, surface->VPeriod());
        if (!uWhole && !vWhole) throw;
        b = GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1));
    }
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
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    PlacementSurface p;
    p.trim = detail::faceTrim(face, b, reversed);
    if (p.trim) p.trimEdges = p.trim->edges.size();
    if (reversed) b->UReverse();  // the normal out of the face's material
    p.surface = detail::nurbsSurface(b);
    p.faceCount = faces.faces.size();
    p.face = which;
    p.faces = {which};
    p.name = faces.names[which];
    return p;
}

}  // namespace

PlacementSurface readPlacementSurface(const std::string& path, std::size_t which)
{
    if (lowerExtension(path) == ".grid") {
        if (which != 0) throw Error(ErrorCode::InvalidArgument, "a point grid has one surface: face 0", path);
        return detail::readGridSurface(path);
    }
    try {
        const FileFaces faces = readFaces(path);
        if (which >= faces.faces.size())
            throw Error(ErrorCode::InvalidArgument, "face " + std::to_string(which) + " asked for, the file has " + std::to_string(faces.faces.size()) +
                                                        " face(s) (0-based)", path);
        return convertFace(faces, which, path);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed reading the placement surface: ") + e.GetMessageString(), path);
    }
}

PlacementSurface readPlacementSurface(const std::string& path, const std::vector<std::size_t>& which)
{
    if (which.empty()) throw Error(ErrorCode::InvalidArgument, "no faces asked for", path);
    if (which.size() == 1) return readPlacementSurface(path, which.front());
    if (lowerExtension(path) == ".grid") throw Error(ErrorCode::InvalidArgument, "a point grid has one surface: face 0", path);
    try {
        const FileFaces faces = readFaces(path);
        std::vector<Handle(Geom_BSplineSurface)> surfaces;
        std::vector<std::string> names;
        std::string joinedName;
        for (std::size_t k = 0; k < which.size(); ++k) {
            const std::size_t f = which[k];
            if (f >= faces.faces.size())
                throw Error(ErrorCode::InvalidArgument, "face " + std::to_string(f) + " asked for, the file has " + std::to_string(faces.faces.size()) +
                                                            " face(s) (0-based)", path);
            if (std::find(which.begin(), which.begin() + static_cast<std::ptrdiff_t>(k), f) != which.begin() + static_cast<std::ptrdiff_t>(k))
                throw Error(ErrorCode::InvalidArgument, "face " + std::to_string(f) + " asked for twice", path);
            const PlacementSurface one = convertFace(faces, f, path);
            names.push_back("face " + std::to_string(f) + (one.name.empty() ? "" : " '" + one.name + "'"));
            if (one.trim) throw Error(ErrorCode::InvalidArgument, names.back() + " is trimmed: a shell is joined from whole faces (their (u,v) boxes)", path);
            surfaces.push_back(detail::occtSurface(one.surface));
            if (!one.name.empty()) joinedName += (joinedName.empty() ? "" : "+") + one.name;
        }
        PlacementSurface out;
        try {
            out.surface = detail::nurbsSurface(detail::joinFaces(surfaces, names));
        } catch (const Error& e) {
            throw Error(e.code(), e.message(), path);
        }
        out.faceCount = faces.faces.size();
        out.face = which.front();
        out.faces = which;
        out.name = joinedName;
        return out;
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed joining the faces: ") + e.GetMessageString(), path);
    }
}

PlacementSurface readPlacementSurface(const std::string& path, const std::string& faceName)
{
    if (lowerExtension(path) == ".grid") throw Error(ErrorCode::InvalidArgument, "a point grid has no named faces (face 0 is its surface)", path);
    if (faceName.empty()) throw Error(ErrorCode::InvalidArgument, "an empty face name", path);
    try {
        const FileFaces faces = readFaces(path);
        std::string known;
        for (std::size_t k = 0; k < faces.faces.size(); ++k) {
            if (faces.names[k] == faceName) return convertFace(faces, k, path);
            if (!faces.names[k].empty() && known.size() < 200) known += (known.empty() ? "'" : ", '") + faces.names[k] + "'";
        }
        throw Error(ErrorCode::InvalidArgument, "no face named '" + faceName + "' (" + (known.empty() ? std::string("its faces have no names") : "names: " + known) + ")",
                    path);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed reading the placement surface: ") + e.GetMessageString(), path);
    }
}

TOWGEOM_END_NAMESPACE
