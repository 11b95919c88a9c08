// towgeom: the command-line front end of the towgeom library.
#include <cstring>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/progress_printer.hpp"
#include "towgeom/error.hpp"
#include "towgeom/version.hpp"

namespace towgeom::cli {

namespace {
const char* kHelp = R"(Usage: towgeom COMMAND [options]

towgeom turns the interpenetrating tows of a textile model into exact NURBS surfaces
and compatible finite-element meshes.

Commands:
  fit       fit B-spline surfaces to tow stacks (.stw) and report accuracy and volume
  detect    find every interpenetration between tows as intersection loops (JSON)
  resolve   mesh every tow and make the meshes compatible where tows interpenetrate
            (shared connected regions; STL, VTK, Gmsh .msh, Abaqus .inp, report.json)
  export    the resolved tows (and, in a cell, the matrix) as exact trimmed B-spline solids:
            STEP AP214, OpenCASCADE BREP
  generate  generate a woven textile (plain, twill, satin, basket, 3D orthogonal) as tow
            stacks, with controlled overlap or flattened to just touching
  ply       fibre placement: plies on a tool surface (STEP, IGES) as trivariate NURBS for
            isogeometric analysis (offsets keeping the surface's parametrisation)
  courses   fibre placement: courses of tows on a tool surface offset from a reference
            curve (Schueler et al. or exact geodesics), laminate-family plies at an angle,
            gaps and overlaps between tows, tows as .stw ribbons for detect
  stiffness the 6x6 effective stiffness of a periodic cell from CalculiX's output of the
            load cases `resolve --load-cases` wrote (JSON)

Run 'towgeom COMMAND --help' for a command's options, inputs and outputs.

The .stw format: '#' comments, an optional 'tow NAME' line, then sections of N lines
'x y z' separated by blank lines, all with the same N, in order along the tow.

Options:
  -h, --help     this help
  --version      the library version
)";
}  // namespace

int reportError(const char* command, const std::exception& e)
{
    const auto* stopped = dynamic_cast<const Error*>(&e);
    if (stopped && stopped->code() == ErrorCode::Cancelled) {
        std::cerr << "towgeom " << command << ": stopped by a signal (Ctrl-C or SIGTERM); nothing written [cancelled]\n";
        return kExitCancelled;
    }
    std::string message = e.what();
    for (char& c : message)
        if (c == '\n') c = ' ';
    std::cerr << "towgeom " << command << ": " << message;
    if (dynamic_cast<const UsageError*>(&e)) {
        std::cerr << " (see towgeom " << command << " --help)\n";
        return kExitInput;
    }
    const auto* error = dynamic_cast<const Error*>(&e);
    if (error) std::cerr << " [" << errorCodeName(error->code()) << "]";
    std::cerr << "\n";
    if (error) {
        switch (error->code()) {
        case ErrorCode::Cancelled: return kExitCancelled;
        case ErrorCode::WriteFailed:
        case ErrorCode::Internal: return kExitFailure;
        default: return kExitInput;
        }
    }
    return kExitFailure;
}

}  // namespace towgeom::cli

int main(int argc, char** argv)
{
    using namespace towgeom::cli;
    if (argc < 2) {
        std::cerr << kHelp;
        return kExitInput;
    }
    const char* command = argv[1];
    if (!std::strcmp(command, "-h") || !std::strcmp(command, "--help") || !std::strcmp(command, "help")) {
        std::cout << kHelp;
        return kExitOk;
    }
    if (!std::strcmp(command, "--version")) {
        std::cout << "towgeom " << towgeom::versionString() << "\n";
        return kExitOk;
    }
    try {
        if (!std::strcmp(command, "fit")) return runFit(argc, argv, 2);
        if (!std::strcmp(command, "detect")) return runDetect(argc, argv, 2);
        if (!std::strcmp(command, "resolve")) return runResolve(argc, argv, 2);
        if (!std::strcmp(command, "export")) return runExport(argc, argv, 2);
        if (!std::strcmp(command, "generate")) return runGenerate(argc, argv, 2);
        if (!std::strcmp(command, "ply")) return runPly(argc, argv, 2);
        if (!std::strcmp(command, "courses")) return runCourses(argc, argv, 2);
        if (!std::strcmp(command, "stiffness")) return runStiffness(argc, argv, 2);
    } catch (...) {
        // Commands report their own errors; this is the last guard against an unknown one.
        std::cerr << "towgeom " << command << ": internal error (unexpected exception) [internal]\n";
        return kExitFailure;
    }
    std::cerr << "towgeom: unknown command '" << command << "' (see towgeom --help)\n";
    return kExitInput;
}
