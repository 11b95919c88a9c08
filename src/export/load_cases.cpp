// The six unit-strain load cases of a periodic cell (CalculiX/Abaqus), and the effective
// stiffness read back from CalculiX's element output.
#include "towgeom/load_cases.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "export/number_writer.hpp"
#include "export/volume_mesh_checks.hpp"
#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE

ElasticMaterial ElasticMaterial::isotropic(double e, double nu)
{
    const double g = e / (2.0 * (1.0 + nu));
    return {e, e, e, nu, nu, nu, g, g, g};
}

bool ElasticMaterial::isIsotropic() const
{
    const double g = e1 / (2.0 * (1.0 + nu12));
    const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); };
    return same(e1, e2) && same(e1, e3) && same(nu12, nu13) && same(nu12, nu23) && same(g12, g) && same(g13, g) && same(g23, g);
}

void ElasticMaterial::validate(const std::string& what) const
{
    const double all[9] = {e1, e2, e3, nu12, nu13, nu23, g12, g13, g23};
    for (double x : all)
        if (!std::isfinite(x)) throw Error(ErrorCode::InvalidArgument, what + ": an elastic constant is not a finite number");
    if (!(e1 > 0.0 && e2 > 0.0 && e3 > 0.0 && g12 > 0.0 && g13 > 0.0 && g23 > 0.0))
        throw Error(ErrorCode::InvalidArgument, what + ": Young's and shear moduli must be positive");
    // The compliance matrix's normal block is positive definite (the shear terms are, given
    // G > 0): its leading minors.
    const double nu21 = nu12 * e2 / e1, nu31 = nu13 * e3 / e1, nu32 = nu23 * e3 / e2;
    const double m2 = 1.0 - nu12 * nu21;
    const double det = 1.0 - nu12 * nu21 - nu23 * nu32 - nu13 * nu31 - 2.0 * nu21 * nu32 * nu13;
    if (!(m2 > 0.0 && det > 0.0))
        throw Error(ErrorCode::InvalidArgument, what + ": the Poisson's ratios make the material unstable (its stiffness is not positive "
                                                       "definite; isotropic: -1 < nu < 0.5)");
}

namespace {

/// Voigt order of the load cases and of the stiffness: xx, yy, zz, yz, xz, xy.
constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

void writeMaterial(detail::NumberWriter& w, const char* name, const ElasticMaterial& m)
{
    w.text("*MATERIAL, NAME=").text(name).end();
    if (m.isIsotropic()) {
        w.text("*ELASTIC").end().fitted(m.e1, 20).text(", ").fitted(m.nu12, 20).end();
        return;
    }
    w.text("*ELASTIC, TYPE=ENGINEERING CONSTANTS").end();
    // Eight numbers of at most 14 characters: the line stays under CalculiX's 132.
    const double first[8] = {m.e1, m.e2, m.e3, m.nu12, m.nu13, m.nu23, m.g12, m.g13};
    for (int k = 0; k < 8; ++k) w.fitted(first[k], 14).text(k < 7 ? ", " : "");
    w.end().fitted(m.g23, 20).end();
}

}  // namespace

void writeLoadCases(const TextileMesh& mesh, const VolumeMesh& volumes, const LoadCaseMaterials& materials, std::ostream& out,
                    const std::string& meshFile, const std::string& periodicFile)
{
    if (!mesh.cell || !mesh.cell->box.periodic || !volumes.withMatrix)
        throw Error(ErrorCode::InvalidArgument, "load cases need the volume mesh of a periodic cell (tows and matrix)");
    detail::checkVolumeMeshOf(mesh, volumes);
    materials.tows.validate("the tows' material");
    materials.matrix.validate("the matrix's material");
    if (std::find(volumes.tow.begin(), volumes.tow.end(), mesh.tows.size()) == volumes.tow.end() ||
        std::count(volumes.tow.begin(), volumes.tow.end(), mesh.tows.size()) == static_cast<long>(volumes.tow.size()))
        throw Error(ErrorCode::InvalidArgument, "load cases need tows and matrix in the cell (an element set TEXTILE and MATRIX each)");
    const bool oriented = !materials.tows.isIsotropic();
    if (oriented && volumes.fibreDirection.empty())
        throw Error(ErrorCode::InvalidArgument, "orthotropic tows need the tetrahedra's fibre directions (addFibreDirections())");
    const Point3 size = mesh.cell->box.max - mesh.cell->box.min;
    const double length[3] = {size.x, size.y, size.z};
    detail::NumberWriter w(out);
    w.text("** towgeom: the six unit-strain load cases of a periodic cell (Voigt order xx, yy, zz, yz, xz, xy;").end();
    w.text("** engineering shear strains). Read back with `towgeom stiffness DIR` or readEffectiveStiffness().").end();
    w.text("*INCLUDE, INPUT=").text(meshFile.c_str()).end();
    w.text("*INCLUDE, INPUT=").text(periodicFile.c_str()).end();
    writeMaterial(w, "TOWS", materials.tows);
    writeMaterial(w, "MATRIX", materials.matrix);
    w.text("*SOLID SECTION, ELSET=TEXTILE, MATERIAL=TOWS").text(oriented ? ", ORIENTATION=FIBRES" : "").end();
    w.text("*SOLID SECTION, ELSET=MATRIX, MATERIAL=MATRIX").end();
    const char* ref[3] = {"REF_X", "REF_Y", "REF_Z"};
    for (int k = 0; k < 6; ++k) {
        // The mean strain (symmetric; a shear case's engineering strain split over ij and ji).
        double strain[3][3] = {};
        const int i = kVoigt[k][0], j = kVoigt[k][1];
        const double e = i == j ? kLoadCaseStrain : 0.5 * kLoadCaseStrain;
        strain[i][j] = strain[j][i] = e;
        const char* names[6] = {"eps_xx", "eps_yy", "eps_zz", "gamma_yz", "gamma_xz", "gamma_xy"};
        w.text("** load case ").number(k + 1).text(": mean strain ").text(names[k]).text(" = ").fitted(kLoadCaseStrain, 20).end();
        w.text("*STEP").end().text("*STATIC").end().text("*BOUNDARY, OP=NEW").end().text("CORNER, 1, 3, 0.").end();
        // REF_a moves by the strain times the cell's edge along a: u = eps x.
        for (int a = 0; a < 3; ++a)
            for (int d = 0; d < 3; ++d)
                w.text(ref[a]).text(", ").number(d + 1).text(", ").number(d + 1).text(", ").fitted(strain[d][a] * length[a], 20).end();
        // GLOBAL=YES: the stresses in global axes (with ORIENTATION=FIBRES CalculiX would print
        // the tows' in their fibre axes).
        for (const char* set : {"TEXTILE", "MATRIX"}) w.text("*EL PRINT, ELSET=").text(set).text(", GLOBAL=YES").end().text("S, EVOL").end();
        w.text("*END STEP").end();
    }
    w.flush();
}

double EffectiveStiffness::asymmetry() const
{
    double largest = 0.0, off = 0.0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            largest = std::max(largest, std::abs(c[i][j]));
            off = std::max(off, std::abs(c[i][j] - c[j][i]));
        }
    return largest > 0.0 ? off / largest : 0.0;
}

EffectiveStiffness readEffectiveStiffness(std::istream& dat, const std::string& name)
{
    // CalculiX's blocks: a header line "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for
    // set S and time T" or "volume (element, volume) for set S and time T", then a blank line
    // and one line per element (and integration point).
    struct Step {
        std::map<long, std::array<double, 7>> stress;  // per element: summed sxx..syz, points
        std::map<long, double> volume;
    };
    std::vector<std::pair<std::string, Step>> steps;  // by the time's text, in order
    enum class Block { None, Stress, Volume } block = Block::None;
    Step* step = nullptr;
    std::string line;
    long lineNumber = 0;
    const auto failAt = [&](const std::string& what, long at) { throw Error(ErrorCode::MalformedReport, what, name, static_cast<std::size_t>(at)); };
    const auto fail = [&](const std::string& what) { failAt(what, lineNumber); };
    // Fortran drops the E of a three-digit exponent (1.234567-100): put it back.
    const auto number = [](const std::string& token, double& x) {
        std::string t = token;
        for (std::size_t k = 1; k < t.size(); ++k)
            if ((t[k] == '-' || t[k] == '+') && std::isdigit(static_cast<unsigned char>(t[k - 1]))) {
                t.insert(k, 1, 'E');
                break;
            }
        std::size_t used = 0;
        try {
            x = std::stod(t, &used);
        } catch (const std::exception&) {
            return false;
        }
        return used == t.size() && std::isfinite(x);
    };
    const auto integer = [](const std::string& t, long& x) {
        std::size_t used = 0;
        try {
            x = std::stol(t, &used);
        } catch (const std::exception&) {
            return false;
        }
        return used == t.size();
    };
    while (std::getline(dat, line)) {
        ++lineNumber;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos) continue;
        const bool stress = line.compare(first, 9, "stresses ") == 0, volume = line.compare(first, 7, "volume ") == 0;
        if (stress || volume) {
            const auto at = line.find(" and time ");
            if (at == std::string::npos) fail("a block header without its time");
            std::string time = line.substr(at + 10);
            time.erase(0, time.find_first_not_of(' '));
            if (steps.empty() || steps.back().first != time) steps.emplace_back(time, Step{});
            step = &steps.back().second;
            block = stress ? Block::Stress : Block::Volume;
            continue;
        }
        if (!std::isdigit(static_cast<unsigned char>(line[first]))) {
            block = Block::None;  // another block (displacements, ...)
            continue;
        }
        if (block == Block::None) continue;
        std::istringstream fields(line);
        std::vector<std::string> tokens;
        for (std::string t; fields >> t;) tokens.push_back(t);
        long element = 0;
        if (block == Block::Volume) {
            double v = 0.0;
            if (tokens.size() != 2 || !integer(tokens[0], element) || !number(tokens[1], v))
                fail("an element's volume line does not read as an element and a volume");
            step->volume[element] = v;
        } else {
            long point = 0;
            double s[6];
            bool ok = tokens.size() == 8 && integer(tokens[0], element) && integer(tokens[1], point);
            for (std::size_t k = 0; ok && k < 6; ++k) ok = number(tokens[k + 2], s[k]);
            if (!ok) fail("an element's stress line does not read as element, point and six stresses");
            auto& sum = step->stress[element];
            for (int k = 0; k < 6; ++k) sum[static_cast<std::size_t>(k)] += s[k];
            sum[6] += 1.0;
        }
    }
    if (steps.size() != 6) failAt("the output holds " + std::to_string(steps.size()) + " steps with element stresses, not the 6 load cases", 0);
    EffectiveStiffness out;
    // CalculiX's stress order: sxx, syy, szz, sxy, sxz, syz; Voigt's here: xx, yy, zz, yz, xz, xy.
    constexpr int kFromCcx[6] = {0, 1, 2, 5, 4, 3};
    for (std::size_t k = 0; k < 6; ++k) {
        const Step& s = steps[k].second;
        if (s.stress.empty() || s.stress.size() != s.volume.size())
            failAt("load case " + std::to_string(k + 1) + " (time " + steps[k].first + ") has " + std::to_string(s.stress.size()) +
                 " elements with stresses and " + std::to_string(s.volume.size()) + " with a volume", 0);
        const auto sameElements = [&](const Step& a) {
            return std::equal(a.volume.begin(), a.volume.end(), steps[0].second.volume.begin(), steps[0].second.volume.end(),
                              [](const auto& x, const auto& y) { return x.first == y.first; });
        };
        if (k > 0 && !sameElements(s)) failAt("load case " + std::to_string(k + 1) + " covers other elements than the first", 0);
        out.elements = s.volume.size();
        std::array<double, 6> mean{};
        double total = 0.0;
        auto v = s.volume.begin();
        for (const auto& [element, sum] : s.stress) {
            if (v->first != element) failAt("element " + std::to_string(element) + " has stresses but no volume", 0);
            for (int c = 0; c < 6; ++c) mean[static_cast<std::size_t>(c)] += v->second * sum[static_cast<std::size_t>(kFromCcx[c])] / sum[6];
            total += v->second;
            ++v;
        }
        if (!(total > 0.0)) failAt("load case " + std::to_string(k + 1) + ": the elements' volume is not positive", 0);
        out.volume = total;
        for (std::size_t c = 0; c < 6; ++c) out.c[c][k] = mean[c] / total / kLoadCaseStrain;
    }
    return out;
}

TOWGEOM_END_NAMESPACE
