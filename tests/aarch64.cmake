# Compiles kernel tests for AArch64 (-O3, its batch loops vectorised for NEON, statically
# linked) and runs each under qemu-aarch64: the batch kernels bit for bit the scalar ones,
# and every other check of the test, on another instruction set than the build's.
# Boost.Test is taken header-only (boost/test/included), from the build machine's headers,
# compiled once.
# cmake -DCXX=<aarch64-linux-gnu-g++> -DQEMU=<qemu-aarch64> -DKERNELS=<folder holding impact/>
#       -DBOOST_INCLUDE=<folder holding boost/> -DWORK=<scratch folder> -DTESTS=<tests/>
#       [-DSOURCES=<a.cpp,b.cpp>] -P aarch64.cmake
# Without SOURCES it compiles Boost.Test's runner, which every test links (CTest's fixture
# kernels_aarch64_runner, so that the tests of each source, kernels_aarch64.<name>, run
# beside the rest of the suite).
cmake_minimum_required(VERSION 3.20)
if(NOT BOOST_INCLUDE)
  message(FATAL_ERROR "aarch64.cmake: BOOST_INCLUDE (the folder holding boost/) is not given")
endif()

# Boost.Test's implementation, from its header-only variant, compiled once into an object of
# its own (it defines main, which calls the init_unit_test_suite each test's BOOST_TEST_MODULE
# defines, as the static library would) and linked with every test: compiled into each test
# instead, it took 29 of the 59 s the hostile test's compilation took.
if(NOT SOURCES)
  file(MAKE_DIRECTORY ${WORK})
  file(WRITE ${WORK}/boost_test_runner.cpp "#include <boost/test/included/unit_test.hpp>\n")
  execute_process(
    COMMAND ${CXX} -std=c++17 -O2 -idirafter ${BOOST_INCLUDE} -c ${WORK}/boost_test_runner.cpp -o ${WORK}/boost_test_runner.o
    RESULT_VARIABLE failed
    ERROR_VARIABLE errors)
  if(failed)
    message(FATAL_ERROR "compiling Boost.Test for AArch64 failed:\n${errors}")
  endif()
  return()
endif()
if(NOT EXISTS ${WORK}/boost_test_runner.o)
  message(FATAL_ERROR "${WORK}/boost_test_runner.o is missing: run aarch64.cmake without SOURCES first (CTest's fixture kernels_aarch64_runner)")
endif()
# The hostile sweep's pairs, a twentieth of the native run's: qemu runs them about 20 times
# slower, and long double is IEEE's quadruple there, computed in software (2 000 pairs took
# 150 s, 1 000 take 60 s, 7 Dec 2026). What AArch64 changes is each pair's arithmetic (NEON's
# lanes, its C library), which 1 000 pairs a type and kernel, from the same seeds as the
# native sweep, try as the 20 000 do; the blocks with one hostile lane are tried whole. (At
# 500 the sweep's own statistics fail: more than a twentieth of the fast forms' pairs lie on
# a boundary of the classification, 27 of 500.)
set(ENV{IMPACT_SWEEP_PAIRS} 1000)
string(REPLACE "," ";" sources "${SOURCES}")
foreach(file IN LISTS sources)
  set(source ${TESTS}/${file})
  get_filename_component(name ${source} NAME_WE)
  # The build machine's headers searched after the cross compiler's own (for Boost's, which the
  # cross compiler has not).
  execute_process(
    COMMAND ${CXX} -std=c++17 -O3 -ffp-contract=off -static -I${KERNELS}
            -idirafter ${BOOST_INCLUDE} ${source} ${WORK}/boost_test_runner.o -o ${WORK}/${name}
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
