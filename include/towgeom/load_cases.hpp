/// @file load_cases.hpp
/// @brief Effective stiffness of a periodic cell: the six unit-strain load cases as a
/// CalculiX/Abaqus deck, and the 6x6 stiffness read back from the solver's output.
#pragma once

#include <array>
#include <istream>
#include <ostream>
#include <string>

#include "towgeom/textile_mesh.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Linear elastic constants in a material's axes (for tows: 1 along the fibres, the axes of
/// VolumeMesh::fibreDirection as writeAbaqus() writes them), in the user's units.
struct TOWGEOM_EXPORT ElasticMaterial {
    double e1 = 0.0;    ///< Young's modulus along axis 1 (the fibres)
    double e2 = 0.0;    ///< Young's modulus along axis 2
    double e3 = 0.0;    ///< Young's modulus along axis 3
    double nu12 = 0.0;  ///< Poisson's ratio: contraction along 2 under a stress along 1
    double nu13 = 0.0;  ///< Poisson's ratio: contraction along 3 under a stress along 1
    double nu23 = 0.0;  ///< Poisson's ratio: contraction along 3 under a stress along 2
    double g12 = 0.0;   ///< shear modulus in the 1-2 plane
    double g13 = 0.0;   ///< shear modulus in the 1-3 plane
    double g23 = 0.0;   ///< shear modulus in the 2-3 plane
    /// An isotropic material: Young's modulus @p e, Poisson's ratio @p nu.
    static ElasticMaterial isotropic(double e, double nu);
    /// True if every axis has the same constants and G = E / (2 (1 + nu)).
    bool isIsotropic() const;
    /// @throws towgeom::Error (InvalidArgument) naming @p what unless the compliance matrix is
    /// positive definite (moduli > 0, the Poisson's ratios within their bounds).
    void validate(const std::string& what) const;
};

/// The materials of writeLoadCases(): the tows' (with fibre directions: in their fibre axes) and
/// the matrix's.
struct LoadCaseMaterials {
    ElasticMaterial tows;    ///< the tows' (in their fibre axes)
    ElasticMaterial matrix;  ///< the matrix's (in global axes)
};

/// The strain of each load case (one component, the others zero): small, the solution is linear.
constexpr double kLoadCaseStrain = 1e-3;

/// Writes the six load cases of a periodic cell as one CalculiX/Abaqus deck of six *STEPs: it
/// includes @p meshFile (writeAbaqus(mesh, volumes)'s file) and @p periodicFile
/// (writeAbaqusPeriodic()'s), gives the tows (*ELSET TEXTILE) and the matrix their materials
/// (orthotropic tows with ORIENTATION=FIBRES, so @p volumes needs fibre directions:
/// addFibreDirections()), and in step k prescribes the cell's mean strain e_k =
/// kLoadCaseStrain in Voigt order xx, yy, zz, yz, xz, xy (engineering shear strains, 2 eps_ij)
/// through the reference nodes REF_X, REF_Y, REF_Z, the min corner held. Every step prints each
/// element's stresses (in global axes: GLOBAL=YES) and volume (*EL PRINT S, EVOL) for
/// readEffectiveStiffness(). Run it with
/// `ccx -i NAME` in the directory of the included files.
/// @throws towgeom::Error (InvalidArgument) if @p mesh is not clipped to a periodic cell, has no
/// tow or no matrix tetrahedra in it, a material is invalid, or the tows are not isotropic and @p volumes has no fibre directions.
TOWGEOM_EXPORT void writeLoadCases(const TextileMesh& mesh, const VolumeMesh& volumes, const LoadCaseMaterials& materials, std::ostream& out,
                                   const std::string& meshFile = "textile_volume.inp",
                                   const std::string& periodicFile = "textile_volume_periodic.inp");

/// The cell's effective stiffness from the six load cases.
struct TOWGEOM_EXPORT EffectiveStiffness {
    /// C[i][j]: mean stress i under unit mean strain j, Voigt order xx, yy, zz, yz, xz, xy
    /// (engineering shear strains): mean stress = C mean strain.
    std::array<std::array<double, 6>, 6> c{};
    double volume = 0.0;         ///< the elements' summed volume (the cell's)
    std::size_t elements = 0;    ///< how many elements each case averaged over
    /// max |C_ij - C_ji| / max |C_ij|: 0 for exact periodic solutions up to the solver's accuracy.
    double asymmetry() const;
};

/// Reads CalculiX's .dat output of writeLoadCases()'s deck: per step, the volume-weighted mean
/// of every element's stresses (each integration point's weighted equally within its element:
/// exact for C3D4's one point and for straight-edged C3D10's four equal weights, as
/// meshVolumes() makes them; biased for curved ones) divided by the step's strain. The
/// mean stress of a periodic cell is this volume average, so no reaction force is needed.
/// @p name names the input in messages.
/// @throws towgeom::Error (MalformedReport) naming @p name and the line if a step, an element's stress or its
/// volume is missing, or the steps do not cover the same elements.
TOWGEOM_EXPORT EffectiveStiffness readEffectiveStiffness(std::istream& dat, const std::string& name = "ccx .dat");

TOWGEOM_END_NAMESPACE
