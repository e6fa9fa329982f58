# AddressSanitizer and UndefinedBehaviorSanitizer for every target (IMPACT_SANITIZE, and
# IMPACT_FUZZ, which implies it), included by the top-level CMakeLists.txt before any
# target is made. Any report fails the program that made it: UBSan does not recover, and
# LeakSanitizer fails a program that leaks at exit. GiNaC and CLN are not instrumented.
if(NOT (IMPACT_SANITIZE OR IMPACT_FUZZ))
  return()
endif()

# Left out of UBSan: `null` and `alignment`, which test every pointer a member call or a load
# goes through (GiNaC's expressions are such pointers everywhere) and doubled the build's
# time; a null pointer dereferenced is still caught, by ASan, as a SEGV with its stack (a
# member call or a reference bound through one that touches no memory is not).
# Left out too: `shift-base`, a negative number shifted left. CLN's inline constructors from a
# C integer do so (cln/object.h, cl_combine_impl: cln::cl_I(-2), cl_R > -1, -2 * x), in every
# file that builds a CLN number from a negative int; C++20 defines the result, and GCC and Clang
# have always computed it so. A shift by a negative count or past the width is still caught.
add_compile_options(-fsanitize=address,undefined -fno-sanitize=null,alignment,shift-base -fno-omit-frame-pointer
                    -fno-sanitize-recover=undefined)
# Line tables only, and -O1 (both after the build type's -g and -O2, so that these count):
# reports still name file and line, and the sanitized build compiles and links in far less
# time (a file of the engine: -O1 0.55 of -O2's time, -g1 less than -g's).
add_compile_options(-g1 -O1)
add_link_options(-fsanitize=address,undefined)

# tests/sanitizer.supp is compiled into every program of the build (tests, the build's own
# generators, the fuzzer), so that no one has to remember an environment variable.
set(IMPACT_SUPPRESSIONS ${CMAKE_CURRENT_LIST_DIR}/sanitizer.supp)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${IMPACT_SUPPRESSIONS})
file(READ ${IMPACT_SUPPRESSIONS} IMPACT_LSAN_SUPPRESSIONS)
configure_file(${CMAKE_CURRENT_LIST_DIR}/sanitizer_defaults.cpp.in
               ${CMAKE_CURRENT_BINARY_DIR}/sanitizer_defaults.cpp @ONLY)
add_library(impact_sanitizer_defaults OBJECT ${CMAKE_CURRENT_BINARY_DIR}/sanitizer_defaults.cpp)
link_libraries(impact_sanitizer_defaults)
