// TrimmedBrep's files: STEP AP214 through OpenCASCADE's XDE writer (so that each solid carries
// its tow's name) and OpenCASCADE's native BREP. Both are written under a temporary name in the
// target's directory and renamed into place.
#include <BRepTools.hxx>
#include <Standard_Failure.hxx>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>

#include "brep/named_step.hpp"
#include "brep/trimmed_brep_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::uniqueFile;
using detail::writeReplacing;

/// Writes @p impl's compound as STEP to @p file, each solid named after its tow; false when
/// OCCT could not.
bool writeStepFile(const TrimmedBrep::Impl& impl, const std::string& file)
{
    std::vector<std::pair<TopoDS_Shape, std::string>> parts;
    for (std::size_t k = 0; k < impl.solids.size(); ++k) parts.emplace_back(impl.solids[k], impl.names[k]);
    return detail::writeNamedStep(impl.compound, "textile", parts, file);
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
