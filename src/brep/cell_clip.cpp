#include "brep/cell_clip.hpp"

#include <BOPAlgo_PaveFiller.hxx>
#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapIteratorOfDataMapOfShapeInteger.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListIteratorOfListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "brep/general_fuse.hpp"
#include "brep/measure.hpp"
#include "towgeom/error.hpp"
#include "towgeom/volume_mesh.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

/// Fills @p out from its inside part (when there is one) and the parts cut off (@p outside):
/// its faces on the box are those in @p boxImages (the boolean's images of the box's faces),
/// its cut faces those of them not in @p ownImages (the solid's faces and their images).
void measure(ClippedSolid& out, const TopTools_IndexedMapOfShape& boxImages, const TopTools_IndexedMapOfShape& ownImages,
             const std::vector<TopoDS_Shape>& outside)
{
    if (!out.inside) return;  // wholly outside: nothing to measure
    for (TopExp_Explorer x(*out.inside, TopAbs_FACE); x.More(); x.Next()) {
        if (!boxImages.Contains(x.Current())) continue;
        out.onBox.push_back(TopoDS::Face(x.Current()));
        if (ownImages.Contains(x.Current())) continue;  // its own face coinciding with the box's
        out.cutArea += areaOf(x.Current());
        ++out.cutFaces;
    }
    // The cut-off parts' faces have no holes: quick to integrate (the clipped volume, the whole
    // solid's less theirs, is within kMeasureEps of their volume).
    for (const TopoDS_Shape& part : outside) {
        out.outsideVolume += volumeOf(part);
        out.outsideArea += areaOf(part);
    }
}

/// The faces of @p shape and what @p algorithm made of them (its history).
template <typename Algorithm>
void addImages(const TopoDS_Shape& shape, Algorithm& algorithm, TopTools_IndexedMapOfShape& images)
{
    for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next()) {
        images.Add(x.Current());
        for (TopTools_ListIteratorOfListOfShape m(algorithm.Modified(x.Current())); m.More(); m.Next()) images.Add(m.Value());
    }
}

void refuseSeveral(std::size_t pieces, const std::string& tow)
{
    if (pieces > 1)
        throw Error(ErrorCode::Unsupported, "tow '" + tow + "' is cut into " + std::to_string(pieces) +
                                                " solids by the cell's box: not built as a trimmed B-rep");
}

/// One solid: BRepAlgoAPI_Common and _Cut on one BOPAlgo_PaveFiller.
ClippedSolid clipOne(const TopoDS_Solid& solid, const TopoDS_Shape& box, const std::string& tow)
{
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
    ClippedSolid out;
    std::size_t pieces = 0;
    for (TopExp_Explorer x(common.Shape(), TopAbs_SOLID); x.More(); x.Next(), ++pieces) out.inside = TopoDS::Solid(x.Current());
    refuseSeveral(pieces, tow);
    // The faces on the box: what the boolean made of the box's faces (its history); of them the
    // cut faces are not the tow's own (an end cap coinciding with a box face is kept as the
    // tow's face, and is among the box face's images).
    TopTools_IndexedMapOfShape boxImages, ownImages;
    addImages(box, common, boxImages);
    addImages(solid, common, ownImages);
    std::vector<TopoDS_Shape> outside;
    for (TopExp_Explorer x(cut.Shape(), TopAbs_SOLID); x.More(); x.Next()) outside.push_back(x.Current());
    measure(out, boxImages, ownImages, outside);
    return out;
}

/// Several solids: one general fuse of them all with the box (BRepAlgoAPI_BuilderAlgo), whose
/// splits of a face are the same face in every solid that has it. A solid's part inside the box
/// is its split that is also a split of the box.
std::vector<ClippedSolid> clipTogether(const std::vector<TopoDS_Solid>& solids, const TopoDS_Shape& box,
                                       const std::vector<std::string>& names, const std::string& who)
{
    TopTools_ListOfShape arguments;
    for (const TopoDS_Solid& solid : solids) arguments.Append(solid);
    arguments.Append(box);
    BRepAlgoAPI_BuilderAlgo fuse;
    const std::string failure = runGeneralFuse(fuse, arguments);
    if (!failure.empty()) throw Error(ErrorCode::Internal, who + ": OpenCASCADE's general fuse of their solids with the cell's box " + failure);
    const auto splits = [&](const TopoDS_Shape& s) { return splitsOf(fuse, s); };
    // A solid the box does not cut is one of the box's splits when it lies inside (the general
    // fuse makes one solid of splits bounded by the same faces), not when outside.
    TopTools_IndexedMapOfShape boxParts, boxImages;
    for (const TopoDS_Shape& part : splits(box)) boxParts.Add(part);
    addImages(box, fuse, boxImages);
    std::vector<ClippedSolid> all(solids.size());
    for (std::size_t i = 0; i < solids.size(); ++i) {
        std::vector<TopoDS_Shape> outside;
        std::size_t pieces = 0;
        for (const TopoDS_Shape& part : splits(solids[i])) {
            if (!boxParts.Contains(part)) {
                outside.push_back(part);
                continue;
            }
            all[i].inside = TopoDS::Solid(part);
            ++pieces;
        }
        refuseSeveral(pieces, names[i]);
        TopTools_IndexedMapOfShape ownImages;
        addImages(solids[i], fuse, ownImages);
        measure(all[i], boxImages, ownImages, outside);
    }
    return all;
}

}  // namespace

std::vector<ClippedSolid> clipSolidsToCell(const std::vector<TopoDS_Solid>& solids, const Cell& cell,
                                           const std::vector<std::string>& names)
{
    std::string who;  // for messages: "tow 'a'" or "tows 'a', 'b'"
    for (const std::string& n : names) who += (who.empty() ? "'" : ", '") + n + "'";
    who = (names.size() == 1 ? "tow " : "tows ") + who;
    try {
        const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(cell.min.x, cell.min.y, cell.min.z),
                                                     gp_Pnt(cell.max.x, cell.max.y, cell.max.z)).Solid();
        if (solids.size() == 1) return {clipOne(solids[0], box, names[0])};
        return clipTogether(solids, box, names, who);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, who + ": OpenCASCADE failed clipping to the cell: " + e.GetMessageString());
    }
}

namespace {

/// Whether @p face's bounding box (BRepBndLib::AddOptimal: tight on B-spline faces) reaches
/// beyond @p box or within @p margin of one of its faces.
bool nearBoxFace(const TopoDS_Face& face, const Cell& box, double margin)
{
    Bnd_Box b;
    BRepBndLib::AddOptimal(face, b, Standard_False, Standard_False);
    if (b.IsVoid()) return true;  // unknown: clipped with its pair, the safe side
    double x0, y0, z0, x1, y1, z1;
    b.Get(x0, y0, z0, x1, y1, z1);
    return x0 <= box.min.x + margin || y0 <= box.min.y + margin || z0 <= box.min.z + margin || x1 >= box.max.x - margin ||
           y1 >= box.max.y - margin || z1 >= box.max.z - margin;
}

std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t t)
{
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
}

/// How many of @p solids have each face (TopoDS IsSame).
template <typename Solids>
TopTools_DataMapOfShapeInteger faceUses(const Solids& solids)
{
    TopTools_DataMapOfShapeInteger uses;
    for (const TopoDS_Shape& solid : solids)
        if (!solid.IsNull())
            for (TopExp_Explorer x(solid, TopAbs_FACE); x.More(); x.Next()) {
                if (!uses.IsBound(x.Current())) uses.Bind(x.Current(), 0);
                ++uses.ChangeFind(x.Current());
            }
    return uses;
}

}  // namespace

ClippedTows clipTowsToCell(const std::vector<TowSurface>& tows, const ResolveResult& r, const std::vector<SharedFace>& shared,
                           std::vector<TopoDS_Solid>& built, std::vector<BrepSolid>& solids, bool areas)
{
    const Cell& box = r.mesh.cell->box;
    // Groups: tows joined by a shared face that reaches a face of the box, but pairs that still
    // overlap (their common part would be a piece of both).
    std::set<std::pair<std::size_t, std::size_t>> overlapping;
    for (const UnresolvedPairEntry& p : overlappingPairs(r)) overlapping.insert(std::minmax(p.towA, p.towB));
    std::vector<std::size_t> parent(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) parent[t] = t;
    for (const SharedFace& f : shared) {
        if (overlapping.count(std::minmax(f.towA, f.towB))) continue;
        const double margin = 0.05 * std::min(tows[f.towA].towSize(), tows[f.towB].towSize());
        if (nearBoxFace(f.face, box, margin)) parent[rootOf(parent, f.towA)] = rootOf(parent, f.towB);
    }
    std::map<std::size_t, std::vector<std::size_t>> groups;
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (!built[t].IsNull()) groups[rootOf(parent, t)].push_back(t);

    ClippedTows out;
    for (const auto& [root, members] : groups) {
        std::vector<TopoDS_Solid> group;
        std::vector<std::string> names;
        for (std::size_t t : members) {
            group.push_back(built[t]);
            names.push_back(tows[t].name());
        }
        const std::vector<ClippedSolid> clipped = clipSolidsToCell(group, box, names);
        for (std::size_t i = 0; i < members.size(); ++i) {
            const std::size_t t = members[i];
            const ClippedSolid& c = clipped[i];
            BrepSolid& s = solids[t];
            const bool meshed = !r.mesh.tows[t].triangles.empty();
            if (c.inside.has_value() != meshed)
                throw Error(ErrorCode::Internal, "tow '" + tows[t].name() + "': OpenCASCADE's boolean keeps " +
                                                     (meshed ? "nothing" : "a part") + " of its solid inside the cell, its mesh " +
                                                     (meshed ? "a part" : "nothing"));
            if (!c.inside) {  // wholly outside: no solid
                built[t].Nullify();
                s.volume = s.area = 0.0;
                s.faces = s.sharedFaces = s.loops = 0;
                continue;
            }
            // What the box cuts off measured (faces without holes), the rest kept.
            s.volume -= c.outsideVolume;
            s.area += 2.0 * c.cutArea - c.outsideArea;
            s.cellFaces = c.cutFaces;
            built[t] = *c.inside;
            out.onBox.insert(out.onBox.end(), c.onBox.begin(), c.onBox.end());
        }
    }
    // The faces two clipped solids share: those shared before, or their parts inside.
    const TopTools_DataMapOfShapeInteger uses = faceUses(built);
    std::vector<std::size_t> sharedBefore(tows.size(), 0);
    for (const SharedFace& f : shared) ++sharedBefore[f.towA], ++sharedBefore[f.towB];
    for (TopTools_DataMapIteratorOfDataMapOfShapeInteger it(uses); it.More(); it.Next()) out.sharedFaces += it.Value() > 1;
    TopTools_IndexedMapOfShape onBox;
    for (const TopoDS_Face& f : out.onBox) onBox.Add(f);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        if (built[t].IsNull()) continue;
        BrepSolid& s = solids[t];
        s.faces = s.sharedFaces = 0;
        double sharedArea = 0.0, onBoxArea = 0.0;  // its faces the matrix does not have: shared ones, those on the box
        for (TopExp_Explorer x(built[t], TopAbs_FACE); x.More(); x.Next()) {
            ++s.faces;
            const bool isShared = uses.Find(x.Current()) > 1;
            s.sharedFaces += isShared;
            if (!areas) continue;
            if (isShared)
                sharedArea += areaOf(x.Current());
            else if (onBox.Contains(x.Current()))
                onBoxArea += areaOf(x.Current());
        }
        // A pair that still overlaps is clipped tow by tow (its common part would be a piece of
        // both in a joint clip), so a face it shares that the box cuts is cut twice.
        const auto partner = std::find_if(shared.begin(), shared.end(), [&](const SharedFace& f) {
            return (f.towA == t || f.towB == t) && overlapping.count(std::minmax(f.towA, f.towB));
        });
        if (s.sharedFaces < sharedBefore[t] && partner != shared.end())
            throw Error(ErrorCode::Unsupported, "tows '" + tows[partner->towA].name() + "' and '" + tows[partner->towB].name() +
                                                    "' share a face and still overlap (a pair left unresolved): clipped one by one, the "
                                                    "part of that face the cell's box keeps is not shared");
        if (s.sharedFaces < sharedBefore[t])
            throw Error(ErrorCode::Internal, "tow '" + tows[t].name() + "': clipped to the cell it keeps " + std::to_string(s.sharedFaces) +
                                                 " of the " + std::to_string(sharedBefore[t]) + " faces it shares with other tows");
        if (areas) {
            out.onBoxAreas += onBoxArea;
            out.freeAreas += s.area - onBoxArea - sharedArea;
        }
    }
    return out;
}

namespace {

/// The box of @p cell (a new one: a boolean may raise tolerances on its arguments) minus
/// @p tools by OpenCASCADE's boolean cut with the gluing option @p glue, and the box's faces or
/// what the cut made of them in @p boxFaces; empty, with @p why, when the boolean fails or throws,
/// a piece fails BRepCheck_Analyzer, or the pieces' faces on the tows are not exactly
/// @p expected (the tows' faces no other tow shares and not on the box), each once.
std::vector<TopoDS_Solid> cutBox(const Cell& cell, const TopTools_ListOfShape& tools, BOPAlgo_GlueEnum glue,
                                 const TopTools_IndexedMapOfShape& towFaces, const TopTools_IndexedMapOfShape& expected,
                                 TopTools_IndexedMapOfShape& boxFaces, std::string& why)
{
    std::vector<TopoDS_Solid> pieces;
    try {
        const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(cell.min.x, cell.min.y, cell.min.z),
                                                     gp_Pnt(cell.max.x, cell.max.y, cell.max.z)).Solid();
        TopTools_ListOfShape arguments;
        arguments.Append(box);
        BRepAlgoAPI_Cut cut;
        cut.SetArguments(arguments);
        cut.SetTools(tools);
        cut.SetGlue(glue);
        cut.SetRunParallel(Standard_True);
        cut.Build();
        if (!cut.IsDone() || cut.HasErrors()) {
            why = "OpenCASCADE's boolean cut of the box by the tows failed";
            return {};
        }
        TopTools_DataMapOfShapeInteger seen;  // the tows' faces in the pieces, how often
        for (TopExp_Explorer x(cut.Shape(), TopAbs_SOLID); x.More(); x.Next()) {
            if (!BRepCheck_Analyzer(x.Current()).IsValid()) {
                why = "OpenCASCADE's boolean cut of the box by the tows gave a solid its checker refuses";
                return {};
            }
            for (TopExp_Explorer f(x.Current(), TopAbs_FACE); f.More(); f.Next())
                if (towFaces.Contains(f.Current())) {
                    if (!seen.IsBound(f.Current())) seen.Bind(f.Current(), 0);
                    ++seen.ChangeFind(f.Current());
                }
            pieces.push_back(TopoDS::Solid(x.Current()));
        }
        bool exact = seen.Extent() == expected.Extent();
        for (TopTools_DataMapIteratorOfDataMapOfShapeInteger it(seen); exact && it.More(); it.Next())
            exact = it.Value() == 1 && expected.Contains(it.Key());
        if (pieces.empty() || !exact) {
            why = "OpenCASCADE's boolean cut of the box by the tows did not keep the tows' faces as the matrix's";
            return {};
        }
        boxFaces.Clear();
        for (TopExp_Explorer x(box, TopAbs_FACE); x.More(); x.Next()) {
            boxFaces.Add(x.Current());  // kept as it is where no tow reaches it
            for (TopTools_ListIteratorOfListOfShape m(cut.Modified(x.Current())); m.More(); m.Next()) boxFaces.Add(m.Value());
        }
    } catch (const Standard_Failure& e) {
        why = std::string("OpenCASCADE failed cutting the box by the tows: ") + e.GetMessageString();
        return {};
    }
    return pieces;
}

}  // namespace

MatrixCut cutMatrix(const std::vector<TopoDS_Solid>& tows, const Cell& cell, const std::vector<TopoDS_Face>& onBox)
{
    MatrixCut out;
    if (tows.empty()) {  // no tow inside: the box itself
        out.pieces.push_back(TopoDS::Solid(BRepPrimAPI_MakeBox(gp_Pnt(cell.min.x, cell.min.y, cell.min.z),
                                                               gp_Pnt(cell.max.x, cell.max.y, cell.max.z)).Solid()));
        out.faces = out.cellFaces = 6;
        return out;
    }
    // The tows' faces, and those the matrix must have: no other tow's, not on the box.
    TopTools_ListOfShape tools;
    for (const TopoDS_Solid& t : tows) tools.Append(t);
    const TopTools_DataMapOfShapeInteger uses = faceUses(tows);
    TopTools_IndexedMapOfShape towFaces, expected, boxFaces, onTheBox;
    for (const TopoDS_Face& f : onBox) onTheBox.Add(f);
    for (TopTools_DataMapIteratorOfDataMapOfShapeInteger it(uses); it.More(); it.Next()) {
        towFaces.Add(it.Key());
        if (it.Value() == 1 && !onTheBox.Contains(it.Key())) expected.Add(it.Key());
    }
    // The clipped tows lie inside the box, their cut faces on its faces: the box's faces and
    // theirs overlap without crossing, the case OpenCASCADE's gluing option is for (the 4x4
    // twill cell: 0.4 s instead of 15 s on two cores). Its result is checked; the full boolean
    // is the fallback.
    std::string why;
    out.pieces = cutBox(cell, tools, BOPAlgo_GlueShift, towFaces, expected, boxFaces, why);
    if (out.pieces.empty()) out.pieces = cutBox(cell, tools, BOPAlgo_GlueOff, towFaces, expected, boxFaces, why);
    if (out.pieces.empty()) {
        out.failure = why;
        return out;
    }
    for (const TopoDS_Solid& piece : out.pieces)
        for (TopExp_Explorer x(piece, TopAbs_FACE); x.More(); x.Next()) {
            ++out.faces;
            if (towFaces.Contains(x.Current())) ++out.sharedFaces;
            if (boxFaces.Contains(x.Current())) ++out.cellFaces;
        }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
