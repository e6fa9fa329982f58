# Compiles kernel tests for AArch64 (-O3, its batch loops vectorised for NEON, statically
# linked) and runs each under qemu-aarch64: the batch kernels bit for bit the scalar ones,
# and every other check of the test, on another instruction set than the build's.
# Boost.Test is taken header-only (boost/test/included), from the build machine's headers.
# cmake -DCXX=<aarch64-linux-gnu-g++> -DQEMU=<qemu-aarch64> -DKERNELS=<folder holding impact/>
#       -DBOOST_INCLUDE=<folder holding boost/> -DWORK=<scratch folder> -DTESTS=<tests/>
#       -DSOURCES=<a.cpp,b.cpp> -P aarch64.cmake
cmake_minimum_required(VERSION 3.20)

# <boost/test/unit_test.hpp>, as the tests include it, replaced by the header-only variant,
# which includes the real one in turn.
file(WRITE ${WORK}/shim/boost/test/unit_test.hpp
     "#ifndef IMPACT_AARCH64_BOOST_TEST\n#define IMPACT_AARCH64_BOOST_TEST\n"
     "#include <boost/test/included/unit_test.hpp>\n#else\n"
     "#include_next <boost/test/unit_test.hpp>\n#endif\n")
# The hostile sweep's pairs, fewer than natively: qemu runs them about 20 times slower, and
# long double is IEEE's quadruple there, computed in software.
set(ENV{IMPACT_SWEEP_PAIRS} 2000)
string(REPLACE "," ";" sources "${SOURCES}")
if(NOT BOOST_INCLUDE)
  message(FATAL_ERROR "aarch64.cmake: BOOST_INCLUDE (the folder holding boost/) is not given")
endif()
foreach(file IN LISTS sources)
  set(source ${TESTS}/${file})
  get_filename_component(name ${source} NAME_WE)
  # The build machine's headers searched after the cross compiler's own (for Boost's, which the
  # cross compiler has not).
  execute_process(
    COMMAND ${CXX} -std=c++17 -O3 -ffp-contract=off -static -I${WORK}/shim -I${KERNELS}
            -idirafter ${BOOST_INCLUDE} ${source} -o ${WORK}/${name}
    RESULT_VARIABLE failed
    ERROR_VARIABLE errors)
  if(failed)
    message(FATAL_ERROR "compiling ${source} for AArch64 failed:\n${errors}")
  endif()
  execute_process(COMMAND ${QEMU} ${WORK}/${name} --log_level=message RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${name} failed on AArch64 (qemu-aarch64)")
  endif()
  message(STATUS "${name}: passed on AArch64 (qemu-aarch64)")
endforeach()
