// `towgeom stiffness DIR`: the effective stiffness of a periodic cell from CalculiX's output of
// the load cases `towgeom resolve --load-cases` wrote.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kStiffnessHelp = R"(Usage: towgeom stiffness DIR [options]

Reads DIR/textile_load_cases.dat, CalculiX's output of the six unit-strain load cases that
`towgeom resolve ... --cell ... --periodic --volume --load-cases` wrote as
DIR/textile_load_cases.inp, and prints the cell's 6x6 effective stiffness C as JSON: mean
stress = C mean strain, Voigt order xx, yy, zz, yz, xz, xy (engineering shear strains), in the
units of the materials' moduli. Each load case's mean stress is the volume average of every
element's stresses (exact for a periodic cell: no reaction forces are needed).

Output: {"order":["xx","yy","zz","yz","xz","xy"],"stiffness":[[6 numbers] x 6],
         "volume" (the elements' summed volume: the cell's),"elements","asymmetry"
         (max |C_ij - C_ji| / max |C_ij|)}

Options:
  --dat FILE    read FILE instead of DIR/textile_load_cases.dat
  -h, --help    this help

Example:
  towgeom resolve weave/*.stw --out cell --cell weave/textile.json --volume --formats inp \
      --load-cases --tow-material 100000,0.3 --matrix-material 3000,0.35
  (cd cell && ccx -i textile_load_cases)
  towgeom stiffness cell

Exit status: 0 success; 2 a missing or malformed file, bad options.
)";

}  // namespace

int runStiffness(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first, {{"help"}, {"dat", true}});
        if (args.has("help")) {
            std::cout << kStiffnessHelp;
            return kExitOk;
        }
        if (args.positional().size() + (args.value("dat") ? 1 : 0) != 1) throw UsageError("give one directory or --dat FILE");
        const std::string path = args.value("dat") ? *args.value("dat")
                                                   : (std::filesystem::path(args.positional()[0]) / "textile_load_cases.dat").string();
        const std::filesystem::path deck = std::filesystem::path(path).replace_extension(".inp");
        std::error_code ec;
        if (std::filesystem::exists(deck, ec) && std::filesystem::last_write_time(deck, ec) > std::filesystem::last_write_time(path, ec))
            throw Error(ErrorCode::MalformedReport, "older than its deck " + deck.string() + ": run ccx on the new deck first", path);
        std::ifstream in(path);
        if (!in) throw Error(ErrorCode::FileNotFound, "cannot read CalculiX's output (run `ccx -i textile_load_cases` in the directory first)", path);
        const EffectiveStiffness s = readEffectiveStiffness(in, path);
        nlohmann::json c = nlohmann::json::array();
        for (const auto& row : s.c) c.push_back(row);
        const nlohmann::json out = {{"order", {"xx", "yy", "zz", "yz", "xz", "xy"}},
                                    {"stiffness", c},
                                    {"volume", s.volume},
                                    {"elements", s.elements},
                                    {"asymmetry", s.asymmetry()}};
        std::cout << out.dump() << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return reportError("stiffness", e);
    }
}

}  // namespace towgeom::cli
