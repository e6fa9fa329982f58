# Fails unless every batch loop (a loop marked IMPACT_INDEPENDENT_ITERATIONS in a generated
# header) is vectorised at -O3 with no other flag by GCC for AVX2 with FMA and for AVX-512
# (-march=x86-64-v3, x86-64-v4), by Clang for both, and by GCC for AArch64 (compiled
# only, so any x86-64 machine can run it; a compiler not found is skipped with a note), and
# for AVX2 under -ffast-math by both: a
# change to the generated code can keep every result and still lose the vectors. A loop
# that takes a square root is the exception: a C library's sqrt may set errno, so without
# -fno-math-errno neither GCC nor Clang vectorises it, whatever the loop; such a loop must
# vectorise with -fno-math-errno, and nothing else.
# cmake -DGXX=<g++> -DCLANGXX=<clang++> -DAARCH64_GXX=<aarch64-linux-gnu-g++>
#       -DKERNELS=<folder holding impact/> -DSOURCE=<batch_loops.cpp> -P vectorised.cmake
# (GXX is required; CLANGXX and AARCH64_GXX may be empty or NOTFOUND.) -DONLY=<target>
# checks one of the targets below (a compiler and its flags), so that a test each can run
# beside the others: each compiles every batch kernel twice at -O3.
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

function(report_of target extra out)
  execute_process(
    COMMAND ${compiler_${target}} -std=c++17 -O3 ${flags_${target}} ${extra} -ffp-contract=off
            -I${KERNELS} -c ${SOURCE} -o /dev/null
    RESULT_VARIABLE failed
    OUTPUT_VARIABLE report_out
    ERROR_VARIABLE report)
  if(failed)
    message(FATAL_ERROR "compiling ${SOURCE} for ${target} ${extra} failed:\n${report}")
  endif()
  set(${out} "${report_out}${report}" PARENT_SCOPE)
endfunction()

set(failures "")
foreach(target IN LISTS targets)
  report_of(${target} "" plain)
  # -ffast-math implies -fno-math-errno: the report with it is the first one.
  set(no_errno "")
  if(rooted AND "-ffast-math" IN_LIST flags_${target})
    set(no_errno "${plain}")
  elseif(rooted)
    report_of(${target} "-fno-math-errno" no_errno)
  endif()
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
      if(plain MATCHES "${pattern}")
        set(how "${how}, and without")
      endif()
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
