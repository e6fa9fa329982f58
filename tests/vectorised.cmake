# Fails unless every batch loop (a loop marked IMPACT_INDEPENDENT_ITERATIONS in a generated
# header) is vectorised at -O3 with no other flag by GCC for AVX2 with FMA and for AVX-512
# (-march=x86-64-v3, x86-64-v4), by Clang for both, and by GCC for AArch64 (compiled
# only, so any x86-64 machine can run it; a compiler not found is skipped with a note), and
# for AVX2 under -ffast-math by both: a
# change to the generated code can keep every result and still lose the vectors. A loop
# that takes a square root is the exception: a C library's sqrt may set errno, so without
# -fno-math-errno neither GCC nor Clang vectorises it, whatever the loop; such a loop must
# vectorise with -fno-math-errno, and nothing else. Each compiles with -Wall -Wextra
# too, and fails on any warning: a user who builds with `-Wall -Werror` must be able to
# include the headers (Clang's -Wbitwise-instead-of-logical took a loop's `&` of two
# conditions for a mistyped `&&`).
# cmake -DGXX=<g++> -DCLANGXX=<clang++> -DAARCH64_GXX=<aarch64-linux-gnu-g++>
#       -DKERNELS=<folder holding impact/> -DSOURCE=<batch_loops.cpp> -P vectorised.cmake
# (GXX is required; CLANGXX and AARCH64_GXX may be empty or NOTFOUND.) -DONLY=<target>
# checks one of the targets below (a compiler and its flags), so that a test each can run
# beside the others. Each compiles every batch kernel once at -O3: SOURCE's instantiations
# are split in two, those of headers whose loops take no square root (compiled as they are)
# and those of headers whose loops take one (compiled with -fno-math-errno); compiling the
# whole of SOURCE both ways, as this did before, doubled the time of five of the seven tests.
cmake_minimum_required(VERSION 3.20)

# The batch loops, as header:line of the `for`, and those that take a square root. (Read
# whole: file(STRINGS) drops empty lines and joins lines at unbalanced brackets.)
file(GLOB headers ${KERNELS}/impact/*.hpp)
set(loops "")
set(rooted "")
set(marker "\n    IMPACT_INDEPENDENT_ITERATIONS\n")
foreach(header ${headers})
  file(READ ${header} text)
  get_filename_component(name ${header} NAME)
  set(offset 0)
  while(TRUE)
    string(SUBSTRING "${text}" ${offset} -1 rest)
    string(FIND "${rest}" "${marker}" at)
    if(at EQUAL -1)
      break()
    endif()
    math(EXPR offset "${offset} + ${at} + 1")
    string(SUBSTRING "${text}" 0 ${offset} before)
    string(REGEX MATCHALL "\n" newlines "${before}")
    list(LENGTH newlines lines)
    math(EXPR loop "${lines} + 2")  # the marker's line is lines + 1
    list(APPEND loops "${name}:${loop}")
    string(SUBSTRING "${rest}" ${at} -1 body)
    string(FIND "${body}" "\n    }\n" end)  # the loop's end
    string(SUBSTRING "${body}" 0 ${end} body)
    string(FIND "${body}" "std::sqrt(" root)
    if(NOT root EQUAL -1)
      list(APPEND rooted "${name}:${loop}")
    endif()
  endwhile()
endforeach()
list(REMOVE_DUPLICATES rooted)
list(LENGTH loops count)
if(count EQUAL 0)
  message(FATAL_ERROR "no batch loop found in ${KERNELS}/impact")
endif()

# Each target: a label, a compiler, its flags, and the line its report gives a vectorised loop.
set(gcc_said ": optimized: loop vectorized")
set(clang_said ": remark: vectorized loop")
set(targets "")
set(known "")
macro(add_target label compiler flags said)
  list(APPEND known ${label})
  if(DEFINED ONLY AND NOT "${ONLY}" STREQUAL "${label}")
    # another test checks it
  elseif(NOT "${compiler}" STREQUAL "" AND NOT "${compiler}" MATCHES "NOTFOUND$")
    list(APPEND targets ${label})
    set(compiler_${label} ${compiler})
    set(flags_${label} ${flags})
    set(said_${label} "${said}")
  else()
    message(STATUS "${label}: no compiler found, not checked")
  endif()
endmacro()
add_target(gcc-x86-64-v3 "${GXX}" "-march=x86-64-v3;-fopt-info-vec-optimized" "${gcc_said}")
add_target(gcc-x86-64-v4 "${GXX}" "-march=x86-64-v4;-fopt-info-vec-optimized" "${gcc_said}")
add_target(clang-x86-64-v3 "${CLANGXX}" "-march=x86-64-v3;-Rpass=loop-vectorize" "${clang_said}")
add_target(clang-x86-64-v4 "${CLANGXX}" "-march=x86-64-v4;-Rpass=loop-vectorize" "${clang_said}")
add_target(gcc-aarch64 "${AARCH64_GXX}" "-fopt-info-vec-optimized" "${gcc_said}")
# The flags games are built with: the kernels' precise pragmas (common.hpp) must keep the vectors.
add_target(gcc-x86-64-v3-fast-math "${GXX}" "-march=x86-64-v3;-ffast-math;-fopt-info-vec-optimized" "${gcc_said}")
add_target(clang-x86-64-v3-fast-math "${CLANGXX}" "-march=x86-64-v3;-ffast-math;-Rpass=loop-vectorize" "${clang_said}")
if(DEFINED ONLY AND NOT ONLY IN_LIST known)
  message(FATAL_ERROR "ONLY=${ONLY}: no such target (${known})")
endif()

# SOURCE's explicit instantiations, each sent to the half its header's loops belong to: the
# header of impact::<name>_batch_data<double, <n>> is <name>_<n>d.hpp, and <name>.hpp for
# n = 0 (a kernel of scalars alone).
file(STRINGS ${SOURCE} source_lines)
set(prelude "")
set(plain_lines "")
set(rooted_lines "")
foreach(line IN LISTS source_lines)
  if(line MATCHES "^template .*impact::([a-z_]+)_batch_data<double, ([0-9])>")
    set(header "${CMAKE_MATCH_1}_${CMAKE_MATCH_2}d.hpp")
    if(CMAKE_MATCH_2 STREQUAL "0")
      set(header "${CMAKE_MATCH_1}.hpp")
    endif()
    if(NOT EXISTS ${KERNELS}/impact/${header})
      message(FATAL_ERROR "${SOURCE}: ${line}\n  instantiates a batch kernel of ${header}, which ${KERNELS}/impact does not hold")
    endif()
    set(rooted_here ${rooted})
    list(FILTER rooted_here INCLUDE REGEX "^${header}:")
    if(rooted_here)
      string(APPEND rooted_lines "${line}\n")
    else()
      string(APPEND plain_lines "${line}\n")
    endif()
  elseif(line MATCHES "^#include")
    string(APPEND prelude "${line}\n")
  endif()
endforeach()
if(NOT DEFINED ONLY)
  set(ONLY all)
endif()
set(plain_source ${CMAKE_CURRENT_BINARY_DIR}/batch_loops-${ONLY}-plain.cpp)
set(rooted_source ${CMAKE_CURRENT_BINARY_DIR}/batch_loops-${ONLY}-rooted.cpp)
file(WRITE ${plain_source} "${prelude}${plain_lines}")
file(WRITE ${rooted_source} "${prelude}${rooted_lines}")

function(report_of target source extra out)
  if(source STREQUAL "")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  execute_process(
    COMMAND ${compiler_${target}} -std=c++17 -O3 -Wall -Wextra ${flags_${target}} ${extra} -ffp-contract=off
            -I${KERNELS} -c ${source} -o /dev/null
    RESULT_VARIABLE failed
    OUTPUT_VARIABLE report_out
    ERROR_VARIABLE report)
  if(failed)
    message(FATAL_ERROR "compiling ${source} for ${target} ${extra} failed:\n${report}")
  endif()
  if(report MATCHES "warning:")
    string(REGEX MATCHALL "[^\n]*warning:[^\n]*" warnings "${report}")
    list(JOIN warnings "\n" warnings)
    message(FATAL_ERROR "compiling ${source} for ${target} ${extra} warned (-Wall -Wextra):\n${warnings}")
  endif()
  set(${out} "${report_out}${report}" PARENT_SCOPE)
endfunction()

set(failures "")
foreach(target IN LISTS targets)
  set(plain_part "")
  set(rooted_part "")
  if(plain_lines)
    set(plain_part ${plain_source})
  endif()
  if(rooted_lines)
    set(rooted_part ${rooted_source})
  endif()
  report_of(${target} "${plain_part}" "" plain)
  # -ffast-math implies -fno-math-errno.
  report_of(${target} "${rooted_part}" "-fno-math-errno" no_errno)
  foreach(loop IN LISTS loops)
    string(REPLACE "." "\\." pattern "${loop}")
    set(pattern "${pattern}:[0-9]+${said_${target}}")
    list(FIND rooted ${loop} root)
    if(root EQUAL -1)
      set(report "${plain}")
      set(how "")
    else()
      set(report "${no_errno}")
      set(how " with -fno-math-errno (it takes a square root)")
    endif()
    if(report MATCHES "${pattern}")
      message(STATUS "${target}: ${loop} vectorised${how}")
    else()
      message(STATUS "${target}: ${loop} NOT vectorised${how}")
      string(APPEND failures "${target}: ${loop}${how}\n")
      file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/vectorised-${target}.log "${plain}\n--- -fno-math-errno ---\n${no_errno}")
    endif()
  endforeach()
endforeach()
if(failures)
  message(FATAL_ERROR "batch loops not vectorised (the compilers' reports are in vectorised-<target>.log):\n${failures}")
endif()
