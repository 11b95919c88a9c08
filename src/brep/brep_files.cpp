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
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <vector>

#include "brep/quiet_messenger.hpp"
#include "brep/trimmed_brep_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// A new empty file named @p prefix + 6 random characters + @p suffix (mkstemps: no other
/// writer, thread or process, gets the same name); its name.
std::string uniqueFile(const std::string& prefix, const std::string& suffix)
{
    std::string name = prefix + "XXXXXX" + suffix;
    const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
    if (fd < 0) throw Error(ErrorCode::WriteFailed, "cannot create a temporary file", prefix + "XXXXXX" + suffix);
    ::close(fd);
    return name;
}

/// Writes @p path through @p write (given a temporary path next to it), then renames the
/// temporary into place; on any failure the temporary is removed and nothing is left.
void writeReplacing(const std::string& path, const std::function<bool(const std::string&)>& write)
{
    const std::string temporary = uniqueFile(path + ".towgeom-", ".tmp");
    bool ok = false;
    std::string why = "write failed";
    try {
        ok = write(temporary);
    } catch (const Standard_Failure& e) {
        why = std::string("OpenCASCADE failed writing it: ") + e.GetMessageString();
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
    if (ok && std::rename(temporary.c_str(), path.c_str()) == 0) return;
    std::remove(temporary.c_str());
    throw Error(ErrorCode::WriteFailed, ok ? "cannot move the written file into place" : why, path);
}

/// The STEP writer's process-wide parameters this file sets, restored when it goes.
class StepParameters {
public:
    StepParameters() : schema_(Interface_Static::CVal("write.step.schema")), names_(Interface_Static::IVal("write.stepcaf.subshapes.name"))
    {
        Interface_Static::SetCVal("write.step.schema", "AP214IS");
        Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);
    }
    ~StepParameters()
    {
        Interface_Static::SetCVal("write.step.schema", schema_.c_str());
        Interface_Static::SetIVal("write.stepcaf.subshapes.name", names_);
    }
    StepParameters(const StepParameters&) = delete;
    StepParameters& operator=(const StepParameters&) = delete;

private:
    std::string schema_;
    int names_;
};

/// An XDE document, closed when it goes.
class XdeDocument {
public:
    XdeDocument() { XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc_); }
    ~XdeDocument() { XCAFApp_Application::GetApplication()->Close(doc_); }
    XdeDocument(const XdeDocument&) = delete;
    XdeDocument& operator=(const XdeDocument&) = delete;
    const Handle(TDocStd_Document)& get() const { return doc_; }

private:
    Handle(TDocStd_Document) doc_;
};

/// Writes @p impl's compound as STEP to @p file; false when OCCT could not.
bool writeStepFile(const TrimmedBrep::Impl& impl, const std::string& file)
{
    const std::lock_guard<std::mutex> lock(detail::dataExchangeMutex());
    const detail::QuietMessenger quiet;
    const XdeDocument doc;
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc.get()->Main());
    // One shape (the compound, not an assembly) whose sub-shapes, the solids, carry names.
    const TDF_Label root = shapes->AddShape(impl.compound, Standard_False);
    TDataStd_Name::Set(root, "textile");
    for (std::size_t k = 0; k < impl.solids.size(); ++k) {
        const TDF_Label sub = shapes->AddSubShape(root, impl.solids[k]);
        if (!sub.IsNull()) TDataStd_Name::Set(sub, TCollection_ExtendedString(impl.names[k].c_str(), Standard_True));
    }
    STEPCAFControl_Writer writer;  // first: it registers the parameters set next
    const StepParameters parameters;
    writer.SetNameMode(Standard_True);
    return writer.Transfer(doc.get(), STEPControl_AsIs) && writer.Write(file.c_str()) == IFSelect_RetDone;
}

}  // namespace

void TrimmedBrep::writeStep(const std::string& path) const
{
    writeReplacing(path, [&](const std::string& file) { return writeStepFile(*impl_, file); });
}

void TrimmedBrep::writeBrep(const std::string& path) const
{
    writeReplacing(path, [&](const std::string& file) {
        std::ofstream out(file, std::ios::binary);
        if (!out) return false;
        writeBrep(out);
        out.close();
        return static_cast<bool>(out);
    });
}

void TrimmedBrep::writeStep(std::ostream& out) const
{
    const std::string file = uniqueFile((std::filesystem::temp_directory_path() / "towgeom-").string(), ".step");
    bool ok = false;
    std::string why = "cannot write a temporary STEP file " + file;
    try {
        ok = writeStepFile(*impl_, file);
    } catch (const Standard_Failure& e) {
        why = std::string("OpenCASCADE failed writing STEP: ") + e.GetMessageString();
    } catch (...) {
        std::remove(file.c_str());
        throw;
    }
    if (ok) {
        std::ifstream in(file, std::ios::binary);
        out << in.rdbuf();
        ok = static_cast<bool>(in) && static_cast<bool>(out);
        why = "cannot copy the temporary STEP file " + file + " to the stream";
    }
    std::remove(file.c_str());
    if (!ok) throw Error(ErrorCode::WriteFailed, why);
}

void TrimmedBrep::writeBrep(std::ostream& out) const
{
    try {
        BRepTools::Write(impl_->compound, out);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::WriteFailed, std::string("OpenCASCADE failed writing BREP: ") + e.GetMessageString());
    }
    if (!out) throw Error(ErrorCode::WriteFailed, "the BREP stream could not be written");
}

TOWGEOM_END_NAMESPACE
