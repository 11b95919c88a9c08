// The towgeom subcommands. Each returns the process exit code:
//   0 success, 2 bad input or usage (one line on stderr), 1 failure to write or internal error,
//   3 (detect, resolve, export) a tow pair is unresolved: an open intersection curve, tows that overlap
//   without a curve (nested, identical, touching), or (resolve) a loop around a tow; (ply) a ply's
//   offset missed its tolerance.
#pragma once

namespace towgeom::cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitInput = 2;
constexpr int kExitUnresolved = 3;

/// `towgeom fit FILE.stw... [options]`; argv[first] is the first argument after "fit".
int runFit(int argc, char** argv, int first);

/// `towgeom detect FILE.stw... [options]`.
int runDetect(int argc, char** argv, int first);

/// `towgeom resolve FILE.stw... --out DIR [options]`.
int runResolve(int argc, char** argv, int first);

/// `towgeom export FILE.stw... --step FILE [--brep FILE] [options]`.
int runExport(int argc, char** argv, int first);

/// `towgeom generate --weave KIND --out DIR [options]`.
int runGenerate(int argc, char** argv, int first);

/// `towgeom ply SURFACE.step --thickness T --out DIR [options]`.
int runPly(int argc, char** argv, int first);

/// `towgeom courses SURFACE.step --reference REF --tow-width W --out DIR [options]`.
int runCourses(int argc, char** argv, int first);

/// `towgeom stiffness DIR`: the 6x6 effective stiffness from CalculiX's output of the load cases.
int runStiffness(int argc, char** argv, int first);

/// Prints one line "towgeom COMMAND: message" on stderr and returns the exit code for @p e.
int reportError(const char* command, const std::exception& e);

}  // namespace towgeom::cli
