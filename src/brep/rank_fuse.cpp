#include "brep/rank_fuse.hpp"

#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListIteratorOfListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>

#include <numeric>

#include "brep/general_fuse.hpp"
#include "brep/measure.hpp"
#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

/// The faces of @p shape as the fuse left them: each face's splits, or the face itself.
TopTools_IndexedMapOfShape faceImages(BRepAlgoAPI_BuilderAlgo& fuse, const TopoDS_Shape& shape)
{
    TopTools_IndexedMapOfShape out;
    for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next())
        for (const TopoDS_Shape& f : splitsOf(fuse, x.Current())) out.Add(f);
    return out;
}

/// The union of @p pieces (solids of a general fuse): their faces but those two of them share,
/// as they are oriented in their pieces, grouped into closed shells by shared edges, one solid
/// per shell.
std::vector<TopoDS_Solid> unionOf(const std::vector<TopoDS_Shape>& pieces)
{
    TopTools_DataMapOfShapeInteger uses;
    std::vector<TopoDS_Shape> faces;
    for (const TopoDS_Shape& p : pieces)
        for (TopExp_Explorer x(p, TopAbs_FACE); x.More(); x.Next()) {
            if (!uses.IsBound(x.Current())) {
                uses.Bind(x.Current(), 0);
                faces.push_back(x.Current());
            }
            ++uses.ChangeFind(x.Current());
        }
    BRep_Builder b;
    TopoDS_Compound kept;
    b.MakeCompound(kept);
    std::vector<TopoDS_Shape> boundary;
    for (const TopoDS_Shape& f : faces)
        if (uses.Find(f) == 1) {
            boundary.push_back(f);
            b.Add(kept, f);
        }
    // Faces joined across an edge are of one shell.
    TopTools_IndexedMapOfShape index;
    for (const TopoDS_Shape& f : boundary) index.Add(f);
    std::vector<std::size_t> parent(boundary.size());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    const auto root = [&](std::size_t k) {
        while (parent[k] != k) k = parent[k] = parent[parent[k]];
        return k;
    };
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(kept, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int e = 1; e <= edgeFaces.Extent(); ++e) {
        const TopTools_ListOfShape& at = edgeFaces(e);
        if (at.IsEmpty()) continue;
        const std::size_t first = static_cast<std::size_t>(index.FindIndex(at.First()) - 1);
        for (TopTools_ListIteratorOfListOfShape f(at); f.More(); f.Next())
            parent[root(static_cast<std::size_t>(index.FindIndex(f.Value()) - 1))] = root(first);
    }
    std::vector<TopoDS_Shell> shells;
    std::vector<std::size_t> shellOf(boundary.size(), SIZE_MAX);
    for (std::size_t k = 0; k < boundary.size(); ++k) {
        std::size_t& s = shellOf[root(k)];
        if (s == SIZE_MAX) {
            s = shells.size();
            shells.emplace_back();
            b.MakeShell(shells.back());
        }
        b.Add(shells[s], boundary[k]);
    }
    // A shell whose faces (oriented outward from the material) enclose a negative volume bounds
    // a cavity (a tow ranked above lying wholly inside, the tows inside the matrix): it is an
    // inner shell of the smallest solid whose outer shell holds it (the innermost, where outer
    // shells nest). The sign and the comparison need no precision: OCCT's fixed Gauss points,
    // not its adaptive integration.
    std::vector<TopoDS_Solid> out;
    std::vector<double> size;  // each solid's outer volume
    std::vector<TopoDS_Shell> cavities;
    for (TopoDS_Shell& shell : shells) {
        if (!BRep_Tool::IsClosed(shell))
            throw Error(ErrorCode::Internal, "a shell of the general fuse's splits is open (an edge on one face only)");
        shell.Closed(Standard_True);
        GProp_GProps v;
        BRepGProp::VolumeProperties(shell, v);
        if (v.Mass() < 0.0) {
            cavities.push_back(shell);
            continue;
        }
        TopoDS_Solid solid;
        b.MakeSolid(solid);
        b.Add(solid, shell);
        out.push_back(solid);
        size.push_back(v.Mass());
    }
    for (const TopoDS_Shell& cavity : cavities) {
        TopExp_Explorer vertex(cavity, TopAbs_VERTEX);
        const TopoDS_Vertex& at = TopoDS::Vertex(vertex.Current());
        std::size_t holder = out.size();
        for (std::size_t k = 0; k < out.size(); ++k) {
            if (out.size() > 1) {
                BRepClass3d_SolidClassifier inside(out[k], BRep_Tool::Pnt(at), BRep_Tool::Tolerance(at));
                if (inside.State() != TopAbs_IN) continue;
            }
            if (holder == out.size() || size[k] < size[holder]) holder = k;
        }
        if (holder == out.size()) throw Error(ErrorCode::Internal, "a cavity of a solid of the general fuse lies in none of its shells");
        b.Add(out[holder], cavity);
    }
    return out;
}

}  // namespace

RankFusion fuseByRank(const std::vector<TopoDS_Solid>& whole, const std::vector<double>& wholeArea,
                      const std::function<bool(std::size_t, std::size_t)>& above, const std::optional<Cell>& cell,
                      const std::vector<std::string>& names)
{
    const std::size_t n = whole.size();
    RankFusion out;
    out.tows.resize(n);
    try {
        TopTools_ListOfShape arguments;
        for (const TopoDS_Solid& s : whole) arguments.Append(s);
        TopoDS_Shape box;
        if (cell) {
            box = BRepPrimAPI_MakeBox(gp_Pnt(cell->min.x, cell->min.y, cell->min.z), gp_Pnt(cell->max.x, cell->max.y, cell->max.z)).Solid();
            arguments.Append(box);
        }
        BRepAlgoAPI_BuilderAlgo fuse;
        const std::string failure = runGeneralFuse(fuse, arguments);
        if (!failure.empty()) throw Error(ErrorCode::Internal, "OpenCASCADE's general fuse of the tows' solids " + failure);

        // Every split, the tows it lies in (a split inside two tows is a split of both).
        TopTools_IndexedMapOfShape splits;
        std::vector<std::vector<std::size_t>> inTows;
        for (std::size_t t = 0; t < n; ++t)
            for (const TopoDS_Shape& s : splitsOf(fuse, whole[t])) {
                const int k = splits.Add(s);
                if (static_cast<std::size_t>(k) > inTows.size()) inTows.resize(static_cast<std::size_t>(k));
                inTows[static_cast<std::size_t>(k - 1)].push_back(t);
            }
        TopTools_IndexedMapOfShape boxSplits;
        if (cell)
            for (const TopoDS_Shape& s : splitsOf(fuse, box)) boxSplits.Add(s);

        // Each split to the tow ranked above the others it lies in; outside the box, to none.
        std::vector<std::vector<TopoDS_Shape>> kept(n + 1);  // per tow, then the matrix
        for (int k = 1; k <= splits.Extent(); ++k) {
            const TopoDS_Shape& s = splits(k);
            const std::vector<std::size_t>& in = inTows[static_cast<std::size_t>(k - 1)];
            // Its volume, measured once however many tows lose it.
            double volume = -1.0;
            const auto lose = [&](std::size_t t) {
                if (volume < 0.0) volume = volumeOf(s);
                out.tows[t].lostVolume += volume;
            };
            if (cell && !boxSplits.Contains(s)) {
                for (std::size_t t : in) lose(t);
                continue;
            }
            std::size_t top = in.front();
            for (std::size_t t : in)
                if (above(t, top)) top = t;
            for (std::size_t t : in)
                if (t != top && !above(top, t))
                    throw Error(ErrorCode::Internal, "tows '" + names[top] + "' and '" + names[t] + "' overlap and neither ranks above the other");
            kept[top].push_back(s);
            for (std::size_t t : in)
                if (t != top) lose(t);
        }
        if (cell)
            for (int k = 1; k <= boxSplits.Extent(); ++k)
                if (!splits.Contains(boxSplits(k))) kept[n].push_back(boxSplits(k));

        // The unions; which faces each has, and which of them another has too.
        std::vector<FusedSolid*> all;
        for (FusedSolid& t : out.tows) all.push_back(&t);
        all.push_back(&out.matrix);
        TopTools_DataMapOfShapeInteger towUses;  // faces of tows' solids: how many tows have them
        for (std::size_t t = 0; t <= n; ++t) {
            all[t]->solids = unionOf(kept[t]);
            if (t == n) continue;
            for (const TopoDS_Solid& s : all[t]->solids)
                for (TopExp_Explorer x(s, TopAbs_FACE); x.More(); x.Next()) {
                    if (!towUses.IsBound(x.Current())) towUses.Bind(x.Current(), 0);
                    ++towUses.ChangeFind(x.Current());
                }
        }
        const TopTools_IndexedMapOfShape boxFaces = cell ? faceImages(fuse, box) : TopTools_IndexedMapOfShape();
        for (std::size_t t = 0; t <= n; ++t) {
            FusedSolid& f = *all[t];
            TopTools_IndexedMapOfShape own;
            if (t < n) own = faceImages(fuse, whole[t]);
            TopTools_IndexedMapOfShape has;
            for (const TopoDS_Solid& s : f.solids)
                for (TopExp_Explorer x(s, TopAbs_FACE); x.More(); x.Next()) {
                    has.Add(x.Current());
                    ++f.faces;
                    const bool shared = t < n ? towUses.Find(x.Current()) > 1 : towUses.IsBound(x.Current());
                    const bool onBox = boxFaces.Contains(x.Current());
                    f.sharedFaces += shared;
                    if (onBox && !own.Contains(x.Current())) ++f.cellFaces;
                }
            if (t == n) break;
            // Its area: its whole solid's, less its own faces' parts it does not keep, plus the faces
            // it keeps that are not its own (measured, as those on the box and the shared ones).
            f.area = wholeArea[t];
            for (int k = 1; k <= own.Extent(); ++k)
                if (!has.Contains(own(k))) f.area -= areaOf(own(k));
            double sharedArea = 0.0;
            for (int k = 1; k <= has.Extent(); ++k) {
                const bool isOwn = own.Contains(has(k)), shared = towUses.Find(has(k)) > 1, onBox = boxFaces.Contains(has(k));
                const double a = !isOwn || onBox || shared ? areaOf(has(k)) : 0.0;
                if (!isOwn) f.area += a;
                if (onBox)
                    f.onBoxArea += a;
                else if (shared)
                    sharedArea += a;
            }
            f.freeArea = f.area - f.onBoxArea - sharedArea;
        }
        for (TopTools_DataMapOfShapeInteger::Iterator it(towUses); it.More(); it.Next()) out.sharedFaces += it.Value() > 1;
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed in the general fuse of the tows' solids: ") + e.GetMessageString());
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
