#include "towgeom/version.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
const char* versionString() noexcept { return TOWGEOM_VERSION_STRING; }
TOWGEOM_END_NAMESPACE
