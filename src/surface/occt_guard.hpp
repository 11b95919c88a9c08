// OpenCASCADE reports failures as Standard_Failure, which is no std::exception: every public
// entry point that calls OCCT turns it into a towgeom::Error naming the tow and the operation.
#pragma once

#include <Standard_Failure.hxx>

#include <string>

#include "towgeom/error.hpp"

namespace towgeom::detail {

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

}  // namespace towgeom::detail
