// Files replaced whole, and named STEP through OpenCASCADE's XDE writer.
#include "brep/named_step.hpp"

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
#include <mutex>

#include "brep/quiet_messenger.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

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

}  // namespace

std::string uniqueFile(const std::string& prefix, const std::string& suffix)
{
    std::string name = prefix + "XXXXXX" + suffix;
    const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
    if (fd < 0) throw Error(ErrorCode::WriteFailed, "cannot create a temporary file", prefix + "XXXXXX" + suffix);
    ::close(fd);
    return name;
}

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

bool writeNamedStep(const TopoDS_Shape& shape, const std::string& name, const std::vector<std::pair<TopoDS_Shape, std::string>>& parts,
                    const std::string& file)
{
    const std::lock_guard<std::mutex> lock(dataExchangeMutex());
    const QuietMessenger quiet;
    const XdeDocument doc;
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc.get()->Main());
    // One shape (not an assembly) whose sub-shapes carry names.
    const TDF_Label root = shapes->AddShape(shape, Standard_False);
    TDataStd_Name::Set(root, TCollection_ExtendedString(name.c_str(), Standard_True));
    for (const auto& [part, partName] : parts) {
        const TDF_Label sub = shapes->AddSubShape(root, part);
        if (!sub.IsNull()) TDataStd_Name::Set(sub, TCollection_ExtendedString(partName.c_str(), Standard_True));
    }
    STEPCAFControl_Writer writer;  // first: it registers the parameters set next
    const StepParameters parameters;
    writer.SetNameMode(Standard_True);
    return writer.Transfer(doc.get(), STEPControl_AsIs) && writer.Write(file.c_str()) == IFSelect_RetDone;
}

bool writeNamedStep(const std::vector<std::pair<TopoDS_Shape, std::string>>& parts, const std::string& file)
{
    const std::lock_guard<std::mutex> lock(dataExchangeMutex());
    const QuietMessenger quiet;
    const XdeDocument doc;
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc.get()->Main());
    for (const auto& [part, name] : parts) TDataStd_Name::Set(shapes->AddShape(part, Standard_False), TCollection_ExtendedString(name.c_str(), Standard_True));
    STEPCAFControl_Writer writer;  // first: it registers the parameters set next
    const StepParameters parameters;
    writer.SetNameMode(Standard_True);
    return writer.Transfer(doc.get(), STEPControl_AsIs) && writer.Write(file.c_str()) == IFSelect_RetDone;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
