// OpenCASCADE reports failures as Standard_Failure, which is no std::exception: every public
// entry point that calls OCCT turns it into a towgeom::Error naming the tow and the operation.
#pragma once

#include <Standard_Failure.hxx>

#include <string>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

template <class F>
auto guarded(const std::string& tow, const char* operation, F&& body) -> decltype(body())
{
    try {
        return body();
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed in ") + operation + ": " + e.GetMessageString(),
                    tow.empty() ? std::string() : "tow '" + tow + "'");
    }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
