#include "volume/gmsh_library.hpp"

#include <dlfcn.h>

#include <mutex>
#include <string>
#include <stdexcept>

#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

const GmshApi& gmshApi()
{
    static GmshApi api;
    static std::string failure;
    static std::once_flag once;
    std::call_once(once, [] {
        // Only the soname of the version whose gmshc.h this was built with: the C API's
        // signatures change between minor versions (4.9's gmshInitialize takes one more argument).
        const std::string soname = "libgmsh.so." + std::to_string(GMSH_API_VERSION_MAJOR) + "." + std::to_string(GMSH_API_VERSION_MINOR);
        void* lib = dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!lib) {
            const char* why = dlerror();
            failure = "Gmsh's library could not be loaded (" + std::string(why ? why : soname) + "): install it (Debian 12: apt-get install libgmsh" +
                      std::to_string(GMSH_API_VERSION_MAJOR) + "." + std::to_string(GMSH_API_VERSION_MINOR) + ")";
            return;
        }
        const auto resolve = [&](auto& f, const char* name) {
            f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(lib, name));
            if (!f && failure.empty()) failure = std::string("Gmsh's library ") + soname + " lacks the function " + name;
        };
#define TOWGEOM_GMSH_RESOLVE(name) resolve(api.name, #name);
        TOWGEOM_GMSH_FUNCTIONS(TOWGEOM_GMSH_RESOLVE)
#undef TOWGEOM_GMSH_RESOLVE
    });
    if (!failure.empty()) throw Error(ErrorCode::EngineUnavailable, failure);
    return api;
}

std::string gmshLastErrorText(const GmshApi& api)
{
    char* error = nullptr;
    int ierr = 0;
    api.gmshLoggerGetLastError(&error, &ierr);
    std::string message = error ? error : "";
    if (error) api.gmshFree(error);
    return message;
}

std::string gmshLastError(const GmshApi& api)
{
    const std::string message = gmshLastErrorText(api);
    return message.empty() ? std::string("no message") : message;
}

void gmshCheck(const GmshApi& api, int ierr, const char* call)
{
    if (ierr != 0) throw std::runtime_error(std::string(call) + ": " + gmshLastError(api));
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
