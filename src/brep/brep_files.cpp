// TrimmedBrep's files: STEP AP214 through OpenCASCADE's XDE writer (so that each solid carries
// its tow's name) and OpenCASCADE's native BREP. Both are written under a temporary name in the
// target's directory and renamed into place.
#include <BRepTools.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>

#include "brep/trimmed_brep_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// Writes @p path through @p write (given a temporary path next to it), then renames the
/// temporary into place; on any failure the temporary is removed and nothing is left.
void writeReplacing(const std::string& path, const std::function<bool(const std::string&)>& write)
{
    const std::string temporary = path + ".towgeom-" + std::to_string(::getpid()) + ".tmp";
    bool ok = false;
    std::string why = "write failed";
    try {
        ok = write(temporary);
    } catch (const Standard_Failure& e) {
        why = std::string("OpenCASCADE failed writing it: ") + e.GetMessageString();
    }
    if (ok && std::rename(temporary.c_str(), path.c_str()) == 0) return;
    std::remove(temporary.c_str());
    throw Error(ErrorCode::WriteFailed, ok ? "cannot move the written file into place" : why, path);
}

/// Interface_Static is process-wide: one STEP writer at a time.
std::mutex& stepMutex()
{
    static std::mutex m;
    return m;
}

}  // namespace

void TrimmedBrep::writeStep(const std::string& path) const
{
    writeReplacing(path, [&](const std::string& file) {
        const std::lock_guard<std::mutex> lock(stepMutex());
        Handle(TDocStd_Document) doc;
        XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
        const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
        // One shape (the compound, not an assembly) whose sub-shapes, the solids, carry names.
        const TDF_Label root = shapes->AddShape(impl_->compound, Standard_False);
        TDataStd_Name::Set(root, "textile");
        for (std::size_t k = 0; k < impl_->solids.size(); ++k) {
            const TDF_Label sub = shapes->AddSubShape(root, impl_->solids[k]);
            if (!sub.IsNull()) TDataStd_Name::Set(sub, TCollection_ExtendedString(impl_->names[k].c_str(), Standard_True));
        }
        Interface_Static::SetCVal("write.step.schema", "AP214IS");
        Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);
        STEPCAFControl_Writer writer;
        writer.SetNameMode(Standard_True);
        const bool ok = writer.Transfer(doc, STEPControl_AsIs) && writer.Write(file.c_str()) == IFSelect_RetDone;
        Interface_Static::SetIVal("write.stepcaf.subshapes.name", 0);
        XCAFApp_Application::GetApplication()->Close(doc);
        return ok;
    });
}

void TrimmedBrep::writeBrep(const std::string& path) const
{
    writeReplacing(path, [&](const std::string& file) {
        std::ofstream out(file, std::ios::binary);
        if (!out) return false;
        BRepTools::Write(impl_->compound, out);
        out.close();
        return static_cast<bool>(out);
    });
}

TOWGEOM_END_NAMESPACE
