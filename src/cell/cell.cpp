#include "towgeom/cell.hpp"

#include <cmath>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

const char* cellFaceName(CellFace face) noexcept
{
    switch (face) {
    case CellFace::XMin: return "xmin";
    case CellFace::XMax: return "xmax";
    case CellFace::YMin: return "ymin";
    case CellFace::YMax: return "ymax";
    case CellFace::ZMin: return "zmin";
    case CellFace::ZMax: return "zmax";
    }
    return "xmin";
}

const char* cellCutName(CellCut cut) noexcept
{
    switch (cut) {
    case CellCut::Auto: return "auto";
    case CellCut::Parametric: return "parametric";
    case CellCut::Mesh: return "mesh";
    }
    return "auto";
}

void Cell::validate() const
{
    const double lo[3] = {min.x, min.y, min.z}, hi[3] = {max.x, max.y, max.z};
    const char* axis[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]))
            throw Error(ErrorCode::InvalidArgument, std::string("the cell's ") + axis[a] + " bounds must be finite");
        if (!(lo[a] < hi[a]))
            throw Error(ErrorCode::InvalidArgument, std::string("the cell's ") + axis[a] + " minimum must lie below its maximum");
    }
    if (!(periodTolerance > 0.0 && std::isfinite(periodTolerance)))
        throw Error(ErrorCode::InvalidArgument, "the cell's period tolerance must be > 0 and finite");
    if (!(faceSizeGrowth >= 0.0 && std::isfinite(faceSizeGrowth)))
        throw Error(ErrorCode::InvalidArgument, "the growth of the cell's face size must be >= 0 and finite");
    if (!(faceSizeMax >= 1.0 && std::isfinite(faceSizeMax)))
        throw Error(ErrorCode::InvalidArgument, "the cell's largest face size (relative to the tows' size) must be >= 1 and finite");
    if (periodic && cut == CellCut::Mesh)
        throw Error(ErrorCode::InvalidArgument, "a periodic cell is cut parametrically: its faces' nodes must pair up (CellCut::Mesh is not periodic)");
}

double Cell::plane(CellFace face) const
{
    switch (face) {
    case CellFace::XMin: return min.x;
    case CellFace::XMax: return max.x;
    case CellFace::YMin: return min.y;
    case CellFace::YMax: return max.y;
    case CellFace::ZMin: return min.z;
    case CellFace::ZMax: return max.z;
    }
    return min.x;
}

TOWGEOM_END_NAMESPACE
