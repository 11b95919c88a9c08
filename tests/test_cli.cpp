// The towgeom command line: fit's JSON and VTK output, help, usage errors.
#include <catch2/catch.hpp>

#include "analytic_reference.hpp"
#include "cli_runner.hpp"
#include "synthetic_tows.hpp"

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include <sys/wait.h>

namespace fs = std::filesystem;
using towgeom::testing::cli;
using towgeom::testing::jsonNumber;
using towgeom::testing::Run;
using towgeom::testing::slurp;

namespace {

const std::string kTube = std::string(TOWGEOM_EXAMPLE_DATA) + "/straight_tube.stw";

}  // namespace

TEST_CASE("towgeom fit prints the accuracy report and writes VTK", "[cli]")
{
    const fs::path out = fs::temp_directory_path() / ("towgeom_fit_out_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const Run r = cli("fit '" + kTube + "' --out '" + out.string() + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\"name\":\"straight_tube\"") != std::string::npos);
    CHECK(jsonNumber(r.out, "sections") == 21);
    CHECK(jsonNumber(r.out, "points") == 24);
    CHECK(jsonNumber(r.out, "max_deviation") <= 5e-15);  // observed 1.3e-15
    // The tube (r = 0.5, L = 4, 24 points around, coordinates to 12 digits): the fitted section
    // is the periodic cubic B-spline through the 24-gon (testing::uniformBSplineCircle), 1.3e-5
    // below pi r^2; the faceted tube is the prism over the 24-gon, 12 r^2 sin(pi / 12) L.
    const towgeom::testing::BSplineCircle section = towgeom::testing::uniformBSplineCircle(24, towgeom::testing::interpolatingControlRadius(24, 0.5));
    CHECK(jsonNumber(r.out, "volume") == Approx(section.area * 4.0).epsilon(1e-10));
    CHECK(jsonNumber(r.out, "area") == Approx(section.perimeter * 4.0).epsilon(1e-10));
    CHECK(jsonNumber(r.out, "faceted_volume") == Approx(12.0 * 0.25 * std::sin(3.14159265358979323846 / 12.0) * 4.0).epsilon(1e-10));
    CHECK(r.err.find("[1/1] straight_tube") != std::string::npos);  // progress

    const std::string vtk = slurp(out / "straight_tube.vtk");
    REQUIRE(vtk.rfind("# vtk DataFile Version 3.0\n", 0) == 0);
    CHECK(vtk.find("DATASET POLYDATA") != std::string::npos);
    CHECK(vtk.find("POINTS 4392 double") != std::string::npos);  // (3*20+1) x (3*24)
    CHECK(vtk.find("NORMALS normals double") != std::string::npos);
    std::size_t leftovers = 0;
    for (const auto& e : fs::directory_iterator(out)) leftovers += e.path().extension() != ".vtk";
    CHECK(leftovers == 0);
    fs::remove_all(out);
}

TEST_CASE("towgeom fit renumbers sections whose first point drifts and prints the shifts", "[cli][start]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_fit_drift_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // A round tube, clockwise about +x (not reversed): section i starts i points further round.
    const towgeom::TowStack still = towgeom::testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, {9, 12, 0.0, false}, "still");
    towgeom::TowStack drifting = still;
    drifting.name = "drifting";
    for (std::size_t i = 0; i < drifting.sections.size(); ++i)
        std::rotate(drifting.sections[i].begin(), drifting.sections[i].end() - static_cast<long>(i),
                    drifting.sections[i].end());
    for (const towgeom::TowStack* s : {&still, static_cast<const towgeom::TowStack*>(&drifting)}) {
        std::ofstream f(dir / (s->name + ".stw"));
        towgeom::writeStack(f, *s);
    }
    const Run r = cli("fit '" + (dir / "still.stw").string() + "' '" + (dir / "drifting.stw").string() + "' --quiet");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\"shifted_sections\":0,\"start_shifts\":[0,0,0,0,0,0,0,0,0]") != std::string::npos);
    CHECK(r.out.find("\"shifted_sections\":8,\"start_shifts\":[0,1,2,3,4,5,6,7,8]") != std::string::npos);
    CHECK(jsonNumber(r.out, "volume", 1) == jsonNumber(r.out, "volume", 0));
    CHECK(jsonNumber(r.out, "max_deviation", 1) <= 1e-9);
    fs::remove_all(dir);
}

TEST_CASE("towgeom fit --mode controlnet and approximate report their deviations", "[cli]")
{
    const Run net = cli("fit '" + kTube + "' --mode controlnet --quiet");
    REQUIRE(net.status == 0);
    CHECK(net.err.empty());
    // At a control point the curve is at (P[j-1] + 4 P[j] + P[j+1]) / 6: r (1 - (4 + 2 cos 15deg) / 6).
    CHECK(jsonNumber(net.out, "max_deviation") == Approx(0.5 * (1 - (4 + 2 * std::cos(3.14159265358979323846 / 12)) / 6)).epsilon(1e-9));
    CHECK(jsonNumber(net.out, "volume") == Approx(towgeom::testing::uniformBSplineCircle(24, 0.5).area * 4.0).epsilon(1e-10));
    const Run approx = cli("fit '" + kTube + "' --mode approximate --tolerance 1e-3 --quiet");
    REQUIRE(approx.status == 0);
    CHECK(jsonNumber(approx.out, "max_deviation") <= 1e-3);
}

TEST_CASE("an output directory that cannot be made exits 1 and leaves nothing", "[cli]")
{
    const fs::path blocker = fs::temp_directory_path() / ("towgeom_not_a_dir_" + std::to_string(::getpid()));
    { std::ofstream(blocker) << "a file where the output directory should go\n"; }
    const Run r = cli("fit '" + kTube + "' --out '" + (blocker / "sub").string() + "'");
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err.find("[write_failed]") != std::string::npos);
    CHECK(r.err.find(blocker.string()) != std::string::npos);
    fs::remove(blocker);
}

TEST_CASE("towgeom help texts teach every subcommand", "[cli]")
{
    const Run top = cli("--help");
    CHECK(top.status == 0);
    for (const char* command : {"fit", "detect", "resolve", "export", "generate", "ply", "courses"})
        CHECK(top.out.find(std::string("\n  ") + command + " ") != std::string::npos);
    const Run fit = cli("fit --help");
    CHECK(fit.status == 0);
    for (const char* word : {"--mode", "--tolerance", "--out", "start_shifts", "Exit status", "Example"})
        CHECK(fit.out.find(word) != std::string::npos);
    CHECK(cli("--version").out.find(TOWGEOM_VERSION_STRING) != std::string::npos);
    const Run exportHelp = cli("export --help");
    CHECK(exportHelp.status == 0);
    for (const char* word : {"--step", "--brep", "Exit status"}) CHECK(exportHelp.out.find(word) != std::string::npos);
}

TEST_CASE("every subcommand takes each option its --help lists and refuses the other commands' options (CLI11)", "[cli]")
{
    // The options each --help lists (a line starting with --NAME), per command.
    const std::vector<std::string> commands{"fit", "detect", "resolve", "export", "generate"};
    std::map<std::string, std::set<std::string>> documented;
    std::set<std::string> all;
    for (const std::string& c : commands) {
        const Run help = cli(c + " --help");
        REQUIRE(help.status == 0);
        CHECK(cli(c + " -h").out == help.out);
        std::istringstream lines(help.out);
        for (std::string line; std::getline(lines, line);) {
            std::smatch m;
            if (std::regex_search(line, m, std::regex("^  (?:-h, )?--([a-z-]+)"))) {
                documented[c].insert(m[1]);
                all.insert(m[1]);
            }
        }
        CHECK(documented[c].count("help") == 1);
        CHECK(documented[c].size() >= 6);
    }
    for (const std::string& c : commands)
        for (const std::string& name : all) {
            // Given with a value that cannot be a file: a documented option is never "not expected"
            // (it may still be refused for its value, or for missing inputs), an undocumented one is.
            const Run r = cli(c + " --" + name + "=zz_not_a_value --quiet");
            const bool refusedAsUnknown = r.err.find("not expected") != std::string::npos;
            INFO(c << " --" << name << ": " << r.err);
            CHECK(refusedAsUnknown == (documented[c].count(name) == 0));
            CHECK(r.status == 2);  // a usage error: not a crash (-1) nor a sanitizer report (86)
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        }
    // The same errors for every subcommand: a value missing, any value given to a flag.
    const std::map<std::string, std::string> valueOption{{"fit", "--out"}, {"detect", "--tolerance"}, {"resolve", "--out"}, {"export", "--step"}, {"generate", "--out"}};
    for (const std::string& c : commands) {
        const Run missing = cli(c + " " + valueOption.at(c));
        CHECK(missing.status == 2);
        CHECK(missing.err.find(valueOption.at(c) + ": 1 required") != std::string::npos);
        CHECK(missing.err.find("see towgeom " + c + " --help") != std::string::npos);
        for (const char* value : {"3", "true", ""}) {
            const Run flagValue = cli(c + " --quiet=" + value);
            CHECK(flagValue.status == 2);
            CHECK(flagValue.err.find("option --quiet takes no value (see towgeom " + c + " --help)") != std::string::npos);
        }
    }
    // An input's name is taken as it is, also after `--` or in brackets (not a CLI11 list).
    const Run bracketed = cli("fit --quiet '[a.stw,b.stw]'");
    CHECK(bracketed.status == 2);
    CHECK(bracketed.err.find("[a.stw,b.stw]: no such file") != std::string::npos);
    const Run dashed = cli("fit --quiet -- -x.stw");
    CHECK(dashed.err.find("-x.stw: no such file") != std::string::npos);
}

TEST_CASE("usage errors exit 2 with one line on stderr", "[cli]")
{
    for (const std::string& args : std::vector<std::string>{"fit", "fit --bogus x.stw", "frobnicate", "fit '" + kTube + "' --mode fancy",
                                   "fit '" + kTube + "' --tolerance 1e-3", "fit '" + kTube + "' --mode approximate --tolerance -1",
                                   "fit '" + kTube + "' '" + kTube + "'", "fit --quiet=1 '" + kTube + "'", "detect --tolerance"}) {
        {  // a block, not a section: Catch would rerun the whole case per section
            INFO(args);
            const Run r = cli(args);
            CHECK(r.status == 2);
            CHECK(r.out.empty());
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        }
    }
}

TEST_CASE("towgeom generate writes a textile and flattens it to just touching", "[cli][weave]")
{
    const fs::path out = fs::temp_directory_path() / ("towgeom_generate_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const Run r = cli("generate --weave twill --repeat 2/2 --tows 4x4 --overlap 0.08 --flatten 1e-4 --sections 41 "
                      "--points 16 --faceted vtk,stl --quiet --out '" + out.string() + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\"collisions\":{\"yarn_pairs\":0,") != std::string::npos);
    CHECK(r.out.find("\"collisions_before_flattening\":{\"yarn_pairs\":16,") != std::string::npos);
    CHECK(r.out.find("\"crossings\":16,\"per_crossing\":[{\"warp\":\"warp_0\",\"weft\":\"weft_0\",\"x\":0.0,\"y\":0.0,") !=
          std::string::npos);
    CHECK(jsonNumber(r.out, "flattened_crossings") == 16);
    CHECK(jsonNumber(r.out, "max_gap") <= 1e-4);
    CHECK(fs::exists(out / "textile.json"));
    CHECK(fs::exists(out / "weft_3.faceted.vtk"));
    // Binary STL: 80-byte header, a count, 50 bytes per triangle (2 * 40 * 16 sides + 2 * 16 caps).
    const std::size_t triangles = 2 * 40 * 16 + 2 * 16;
    CHECK(fs::file_size(out / "weft_3.faceted.stl") == 84 + 50 * triangles);
    CHECK(towgeom::readStackFile((out / "warp_2.stw").string()).sectionCount() == 41);
    fs::remove_all(out);
}

TEST_CASE("towgeom generate refuses bad options and writes nothing", "[cli][weave]")
{
    const fs::path out = fs::temp_directory_path() / ("towgeom_generate_bad_" + std::to_string(::getpid()));
    for (const std::string& args :
         std::vector<std::string>{"--weave velvet", "--weave satin --repeat 6 --step 2", "--weave twill --repeat 2",
                                  "--weave plain --overlap 1.2", "--weave plain --points 31", "--weave plain --tows 0x4",
                                  "--weave plain --flatten 0", "--weave plain --repeat 2/2", "--weave plain --faceted obj"}) {
        {  // a block, not a section: Catch would rerun the whole case per section
            INFO(args);
            fs::remove_all(out);
            const Run r = cli("generate " + args + " --out '" + out.string() + "'");
            CHECK(r.status == 2);
            CHECK(r.out.empty());
            CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
            CHECK(!fs::exists(out));
        }
    }
    CHECK(cli("generate --help").out.find("--flatten TAU") != std::string::npos);
}

TEST_CASE("a failed fit --out leaves the output directory exactly as it was", "[cli][output]")
{
    // warp_0.vtk, the last file renamed into place, is a directory that is not empty.
    const fs::path out = fs::temp_directory_path() / ("towgeom_fit_rollback_" + std::to_string(::getpid()));
    fs::remove_all(out);
    fs::create_directories(out / "warp_0.vtk");
    std::ofstream(out / "warp_0.vtk" / "inside") << "x";
    std::ofstream(out / "straight_tube.vtk", std::ios::binary) << "older straight_tube.vtk\n";
    const auto before = towgeom::testing::snapshot(out);
    const std::string warp = std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/warp_0.stw";
    const Run r = cli("fit '" + kTube + "' '" + warp + "' --out '" + out.string() + "' --quiet");
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err == "towgeom fit: " + (out / "warp_0.vtk").string() + ": cannot rename into place: Is a directory [write_failed]\n");
    const auto after = towgeom::testing::snapshot(out);
    INFO("after: " << towgeom::testing::names(after));
    CHECK(after == before);
    CHECK(after.at("straight_tube.vtk") == "older straight_tube.vtk\n");
    fs::remove_all(out);
}

TEST_CASE("towgeom fit refuses a tessellation over --max-triangles at once (exit 2)", "[cli][budget]")
{
    const fs::path out = fs::temp_directory_path() / ("towgeom_fit_budget_" + std::to_string(::getpid()));
    fs::remove_all(out);
    // 2 (U - 1) V = 2 x 99999 x 100000 triangles for the one tube (it once ended in
    // std::bad_alloc, exit 1).
    const Run huge = cli("fit '" + kTube + "' --out '" + out.string() + "' --samples 100000,100000 --quiet");
    CHECK(huge.status == 2);
    CHECK(huge.out.empty());
    CHECK(huge.err ==
          "towgeom fit: the tessellations for --out would have 19999800000 triangles (2 (U - 1) V per tow, 1 tows), over the limit "
          "of 20000000; --max-triangles N raises it, a smaller --samples U,V makes fewer [too_large]\n");
    CHECK_FALSE(fs::exists(out));
    // Either side of the limit: --samples 11,10 gives 200 triangles.
    const Run low = cli("fit '" + kTube + "' --out '" + out.string() + "' --samples 11,10 --max-triangles 199 --quiet");
    CHECK(low.status == 2);
    CHECK(low.err.find("would have 200 triangles") != std::string::npos);
    CHECK(low.err.find("over the limit of 199;") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    const Run ok = cli("fit '" + kTube + "' --out '" + out.string() + "' --samples 11,10 --max-triangles 200 --quiet");
    CHECK(ok.status == 0);
    CHECK(slurp(out / "straight_tube.vtk").find("\nPOLYGONS 200 800\n") != std::string::npos);
    CHECK(cli("fit '" + kTube + "' --max-triangles 200").status == 2);  // applies to --out only
    fs::remove_all(out);
}

TEST_CASE("towgeom fit --bezier writes each tow's Bézier extraction, which an independent B-spline evaluation confirms", "[cli][iga][bezier]")
{
    // The JSON read by Python: at 200 random points of random elements, the Bernstein patch of
    // bezier_points equals de Boor's evaluation of the B-spline (u_knots, the unrolled v_knots,
    // control_points of the periodic basis) written with it, bezier_points = C_e^T times the
    // functions' points, and the elements' v functions run on across the seam (mod v_functions).
    const fs::path out = fs::temp_directory_path() / ("towgeom_fit_bezier_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const std::string warp = std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/warp_0.stw";
    const Run r = cli("fit '" + warp + "' --out '" + out.string() + "' --bezier --quiet");
    INFO(r.err);
    REQUIRE(r.status == 0);
    REQUIRE(fs::exists(out / "warp_0_bezier.json"));
    const std::string script = out.string() + "/check.py";
    std::ofstream(script) << R"(import json, math, random, sys
j = json.load(open(sys.argv[1]))
p, q = j['u_degree'], j['v_degree']
U, V, P, nv = j['u_knots'], j['v_knots'], j['control_points'], j['v_functions']
def basis(knots, deg, x, i):  # Cox-de Boor: value of basis function i at x (span-open on the right)
    def N(i, k):
        if k == 0:
            return 1.0 if knots[i] <= x < knots[i + 1] else 0.0
        a = 0.0 if knots[i + k] == knots[i] else (x - knots[i]) / (knots[i + k] - knots[i]) * N(i, k - 1)
        b = 0.0 if knots[i + k + 1] == knots[i + 1] else (knots[i + k + 1] - x) / (knots[i + k + 1] - knots[i + 1]) * N(i + 1, k - 1)
        return a + b
    return N(i, deg)
def bern(n, k, s):
    return math.comb(n, k) * s ** k * (1 - s) ** (n - k)
random.seed(3)
worst_eval, worst_ce, seam_bad = 0.0, 0.0, 0
E = j['elements']
assert j['v_periodic'] and len(P) == j['u_functions'] * nv
for trial in range(200):
    e = random.choice(E)
    s, t = random.random(), random.random()
    u = e['u'][0] + s * (e['u'][1] - e['u'][0]); v = e['v'][0] + t * (e['v'][1] - e['v'][0])
    bz = [sum(bern(p, bu, s) * bern(q, bv, t) * e['bezier_points'][bu + (p + 1) * bv][c] for bu in range(p + 1) for bv in range(q + 1)) for c in range(3)]
    iu0 = e['functions'][0] // nv
    bs = [0.0, 0.0, 0.0]
    for iu in range(iu0, iu0 + p + 1):
        nu = basis(U, p, u, iu)
        for j in range(e['v_span'], e['v_span'] + q + 1):  # unrolled v function j is periodic function j mod nv
            w = nu * basis(V, q, v, j)
            for c in range(3): bs[c] += w * P[iu * nv + j % nv][c]
    seam_bad += [f % nv for f in e['functions'][::p + 1]] != [(e['v_span'] + av) % nv for av in range(q + 1)]
    d = max(abs(bz[c] - bs[c]) for c in range(3))
    worst_eval = d if not d <= worst_eval else worst_eval  # a NaN sticks
    n = (p + 1) * (q + 1)
    for b in range(n):
        x = [sum(e['extraction'][a * n + b] * P[e['functions'][a]][c] for a in range(n)) for c in range(3)]
        d = max(abs(x[c] - e['bezier_points'][b][c]) for c in range(3))
        worst_ce = d if not d <= worst_ce else worst_ce
print(len(E), worst_eval, worst_ce, seam_bad)
)";
    const Run py = towgeom::testing::runShell("/usr/bin/python3 '" + script + "' '" + (out / "warp_0_bezier.json").string() + "' 2>&1");
    INFO(py.out);
    REQUIRE(py.status == 0);
    std::istringstream read(py.out);
    double elements = 0, worstEval = 1, worstCe = 1, seamBad = 1;
    read >> elements >> worstEval >> worstCe >> seamBad;
    CHECK(elements > 100);
    CHECK(seamBad == 0);  // the periodic numbering across the seam
    CHECK(worstEval < 1e-12);  // the tow is about 1 across
    CHECK(worstCe < 1e-12);
    const Run bad = cli("fit '" + warp + "' --bezier --quiet");
    CHECK(bad.status == 2);
    CHECK(bad.err.find("--bezier") != std::string::npos);
    fs::remove_all(out);
}
