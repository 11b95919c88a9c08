// OpenCASCADE's general fuse (BRepAlgoAPI_BuilderAlgo) as the trimmed B-rep uses it: every
// argument split where it meets the others, a split common to several arguments one shape of
// each, a face between splits one face of both.
#pragma once

#include <BOPAlgo_Alerts.hxx>
#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <TopTools_ListIteratorOfListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Runs @p fuse on @p arguments (in parallel, OCCT's thread pool): empty when it succeeded, else
/// what failed ("failed", or the warning of a part it could not build: OCCT 7.6 reports faces
/// its shell splitter or solid builder drops as warnings, and a split lost that way would go
/// unnoticed in volumes taken as the whole's less what is cut off or given away).
inline std::string runGeneralFuse(BRepAlgoAPI_BuilderAlgo& fuse, const TopTools_ListOfShape& arguments)
{
    fuse.SetArguments(arguments);
    fuse.SetRunParallel(Standard_True);
    fuse.Build();
    if (!fuse.IsDone() || fuse.HasErrors()) return "failed";
    if (fuse.HasWarning(STANDARD_TYPE(BOPAlgo_AlertShellSplitterFailed))) return "could not split a shell (BOPAlgo_AlertShellSplitterFailed)";
    if (fuse.HasWarning(STANDARD_TYPE(BOPAlgo_AlertSolidBuilderUnusedFaces)))
        return "left faces out of its solids (BOPAlgo_AlertSolidBuilderUnusedFaces)";
    return {};
}

/// What @p fuse made of @p shape: its splits, or @p shape itself when it was not split.
inline std::vector<TopoDS_Shape> splitsOf(BRepAlgoAPI_BuilderAlgo& fuse, const TopoDS_Shape& shape)
{
    std::vector<TopoDS_Shape> out;
    for (TopTools_ListIteratorOfListOfShape m(fuse.Modified(shape)); m.More(); m.Next()) out.push_back(m.Value());
    if (out.empty() && !fuse.IsDeleted(shape)) out.push_back(shape);
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
