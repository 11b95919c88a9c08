# towgeom_warnings(TARGET): the warning flags towgeom's own code is built with, per compiler.
function(towgeom_warnings target)
  target_compile_options(${target} PRIVATE
    $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Wall -Wextra>
    $<$<CXX_COMPILER_ID:MSVC>:/W4>)
endfunction()
