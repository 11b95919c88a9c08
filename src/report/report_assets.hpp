// The report's JavaScript, embedded at build time (cmake/embed_files.cmake) from the pinned npm
// packages' files in src/report/assets.
#pragma once

#include <cstddef>
#include <string_view>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

extern const unsigned char kChartJs[];        ///< chart.js 4.5.1 dist/chart.umd.min.js
extern const std::size_t kChartJsSize;
extern const unsigned char kThreeJs[];        ///< three 0.169.0 build/three.module.min.js
extern const std::size_t kThreeJsSize;
extern const unsigned char kOrbitControlsJs[];  ///< three 0.169.0 examples/jsm/controls/OrbitControls.js
extern const std::size_t kOrbitControlsJsSize;
extern const unsigned char kChartJsLicence[];  ///< chart.js's LICENSE.md
extern const std::size_t kChartJsLicenceSize;
extern const unsigned char kKurkleColorLicence[];  ///< @kurkle/color's LICENSE.md
extern const std::size_t kKurkleColorLicenceSize;
extern const unsigned char kThreeJsLicence[];  ///< three's LICENSE
extern const std::size_t kThreeJsLicenceSize;

inline std::string_view asset(const unsigned char* bytes, std::size_t size)
{
    return {reinterpret_cast<const char*>(bytes), size};
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
