# Fails unless GCC vectorises the loop of every batch kernel (a loop marked
# IMPACT_INDEPENDENT_ITERATIONS in a generated header) at -O3, for AVX-512 and, with
# -fno-trapping-math, for AVX2 with FMA (compiled only, so any x86-64 machine can run
# it): a change to the generated code can keep every result and still lose the vectors.
# For AVX2, GCC keeps the division of a discarded lane behind a branch unless it may
# assume that floating-point operations do not trap; AVX-512 masks the division instead.
# cmake -DCXX=<g++> -DKERNELS=<folder holding impact/> -DSOURCE=<batch_loops.cpp> -P vectorised.cmake
set(targets "x86-64-v4" "x86-64-v3 -fno-trapping-math")
set(report "")
foreach(target IN LISTS targets)
  separate_arguments(flags UNIX_COMMAND "-march=${target}")
  execute_process(
    COMMAND ${CXX} -std=c++17 -O3 ${flags} -ffp-contract=off -fopt-info-vec-optimized
            -I${KERNELS} -c ${SOURCE} -o /dev/null
    RESULT_VARIABLE failed
    ERROR_VARIABLE target_report)
  if(failed)
    message(FATAL_ERROR "compiling ${SOURCE} for ${target} failed:\n${target_report}")
  endif()
  string(REPLACE "\n" "\n[${target}] " target_report "\n${target_report}")
  string(APPEND report "${target_report}")
endforeach()
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
      foreach(target IN LISTS targets)
        if(NOT report MATCHES "\n\\[${target}\\] [^\n]*${name}:${loop}:[0-9]+: optimized: loop vectorized")
          message(FATAL_ERROR "the batch loop at ${name}:${loop} is not vectorised for ${target}:\n${report}")
        endif()
      endforeach()
      message(STATUS "${name}:${loop}: vectorised for ${targets}")
    endif()
  endforeach()
endforeach()
if(loops EQUAL 0)
  message(FATAL_ERROR "no batch loop found in ${KERNELS}/impact")
endif()
