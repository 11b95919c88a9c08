#include "towgeom/version.hpp"

namespace towgeom {
const char* versionString() noexcept { return TOWGEOM_VERSION_STRING; }
}  // namespace towgeom
