# Fails unless GCC vectorises the loop of every batch kernel (a loop marked
# IMPACT_INDEPENDENT_ITERATIONS in a generated header), as the benchmark compiles it:
# a change to the generated code can keep every result and still lose the vectors.
# cmake -DCXX=<g++> -DKERNELS=<folder holding impact/> -DSOURCE=<batch_loops.cpp> -P vectorised.cmake
execute_process(
  COMMAND ${CXX} -std=c++17 -O3 -march=native -ffp-contract=off -fopt-info-vec-optimized
          -I${KERNELS} -c ${SOURCE} -o /dev/null
  RESULT_VARIABLE failed
  ERROR_VARIABLE report)
if(failed)
  message(FATAL_ERROR "compiling ${SOURCE} failed:\n${report}")
endif()
file(GLOB headers ${KERNELS}/impact/*.hpp)
set(loops 0)
foreach(header ${headers})
  file(STRINGS ${header} lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "^ *IMPACT_INDEPENDENT_ITERATIONS$")
      math(EXPR loop "${number} + 1")
      math(EXPR loops "${loops} + 1")
      get_filename_component(name ${header} NAME)
      if(NOT report MATCHES "${name}:${loop}:[0-9]+: optimized: loop vectorized")
        message(FATAL_ERROR "the batch loop at ${name}:${loop} is not vectorised:\n${report}")
      endif()
      message(STATUS "${name}:${loop}: vectorised")
    endif()
  endforeach()
endforeach()
if(loops EQUAL 0)
  message(FATAL_ERROR "no batch loop found in ${KERNELS}/impact")
endif()
