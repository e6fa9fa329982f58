# The Python package `impact` (docs/python.md): the generated kernels on NumPy arrays, bound
# with pybind11 for Debian's Python. `cmake --build build --target python` puts the package in
# build/python/impact/, so that `PYTHONPATH=build/python python3 -c "import impact"` works.
#
# Included by the top-level CMakeLists.txt after the kernels are generated; expects
# IMPACT_GENERATED, IMPACT_PYTHON_SOURCES, IMPACT_KERNELS_FROM and the target impact_kernels. Sets IMPACT_PYTHON
# (whether the package is built) and IMPACT_PYTHON_EXECUTABLE (the interpreter it is for).

set(IMPACT_PYTHON OFF)
# The interpreter python3-numpy installs into, which need not be the first python3 on PATH
# (a pyenv or a virtual environment may come first): Debian's, where it is, unless
# Python3_EXECUTABLE names another.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "the Python interpreter the package `impact` is built for")
endif()
option(IMPACT_PYTHON_PACKAGE "Build the Python package impact (needs pybind11 and NumPy)" ON)

if(NOT IMPACT_PYTHON_PACKAGE)
  return()
endif()
if(IMPACT_KERNELS_FROM)
  # The bindings are generated with the kernels, from the derivations: a build that copies
  # the kernels has none.
  message(STATUS "Python package impact not built: the kernels are copied from IMPACT_KERNELS_FROM, and "
                 "their bindings are generated only with them")
  return()
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
if(NOT Python3_FOUND)
  message(STATUS "Python package impact not built: no Python 3 with its headers and NumPy "
                 "(Debian: python3-dev python3-numpy; another interpreter: -DPython3_EXECUTABLE=...)")
  return()
endif()
find_package(pybind11 CONFIG QUIET)
if(NOT pybind11_FOUND)
  message(STATUS "Python package impact not built: pybind11 not found (Debian: pybind11-dev)")
  return()
endif()
set(IMPACT_PYTHON ON)
set(IMPACT_PYTHON_EXECUTABLE ${Python3_EXECUTABLE})
message(STATUS "Python package impact built for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}, "
               "NumPy ${Python3_NumPy_VERSION}, pybind11 ${pybind11_VERSION})")

# IMPACT_PYTHON_SOURCES: one translation unit a derivation file (CMakeLists.txt, where
# impact_kernelgen writes them with the kernel headers), compiled side by side.
# NO_EXTRAS: no link-time optimisation (minutes of linking for nothing the kernels need).
pybind11_add_module(impact_python MODULE NO_EXTRAS ${CMAKE_CURRENT_SOURCE_DIR}/src/python/kernel_binding.cpp
                    ${IMPACT_PYTHON_SOURCES})
add_dependencies(impact_python impact_generated_kernels)
target_include_directories(impact_python PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
# The kernels as users compile them (impact::kernels: without FMA contraction), so that the
# results are the C++ kernels' bit for bit.
target_link_libraries(impact_python PRIVATE impact_kernels)
target_compile_options(impact_python PRIVATE -Wall -Wextra)
set_target_properties(impact_python PROPERTIES
  OUTPUT_NAME _impact
  CXX_VISIBILITY_PRESET hidden
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/python/impact)

set(IMPACT_PYTHON_FILES __init__.py batch.py derivation.py)
set(IMPACT_PYTHON_COPIES)
foreach(file IN LISTS IMPACT_PYTHON_FILES)
  add_custom_command(
    OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/python/impact/${file}
    COMMAND ${CMAKE_COMMAND} -E copy ${CMAKE_CURRENT_SOURCE_DIR}/src/python/impact/${file}
            ${CMAKE_CURRENT_BINARY_DIR}/python/impact/${file}
    DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/python/impact/${file}
    VERBATIM)
  list(APPEND IMPACT_PYTHON_COPIES ${CMAKE_CURRENT_BINARY_DIR}/python/impact/${file})
endforeach()
# impact.derive runs the command `impact` (derivation.py): the build tree's here, the
# installed one in the installed package.
file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/python/impact/_executable.py
     CONTENT "IMPACT_EXECUTABLE = \"$<TARGET_FILE:impact>\"\n")
file(GENERATE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/python_install/_executable.py
     CONTENT "IMPACT_EXECUTABLE = \"${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/impact\"\n")
add_custom_target(python ALL DEPENDS impact_python ${IMPACT_PYTHON_COPIES})

# Installed where that interpreter finds it under the prefix: its own folder of packages when
# that is under CMAKE_INSTALL_PREFIX (Debian's /usr/local/lib/python3.X/dist-packages), else
# lib/python3.X/site-packages there.
execute_process(
  COMMAND ${Python3_EXECUTABLE} -c
          "import os, sys, sysconfig; p = sys.argv[1].rstrip('/'); s = sysconfig.get_path('platlib'); print(os.path.relpath(s, p) if s.startswith(p + '/') else 'lib/python%d.%d/site-packages' % sys.version_info[:2])"
          ${CMAKE_INSTALL_PREFIX}
  OUTPUT_VARIABLE IMPACT_PYTHON_SITE OUTPUT_STRIP_TRAILING_WHITESPACE)
set(IMPACT_PYTHON_INSTALL_DIR ${IMPACT_PYTHON_SITE} CACHE PATH
    "where the package impact is installed, under CMAKE_INSTALL_PREFIX (or absolute)")
install(TARGETS impact_python LIBRARY DESTINATION ${IMPACT_PYTHON_INSTALL_DIR}/impact)
list(TRANSFORM IMPACT_PYTHON_FILES PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/src/python/impact/ OUTPUT_VARIABLE IMPACT_PYTHON_SOURCES_PY)
install(FILES ${IMPACT_PYTHON_SOURCES_PY} ${CMAKE_CURRENT_BINARY_DIR}/python_install/_executable.py
        DESTINATION ${IMPACT_PYTHON_INSTALL_DIR}/impact)

# The benchmark of docs/python.md, run by hand, never by CTest:
# `cmake --build build --target benchmark_python`. Its C++ side is compiled as the module is.
add_executable(python_batch_bench EXCLUDE_FROM_ALL ${CMAKE_CURRENT_SOURCE_DIR}/tests/benchmarks/python_batch.cpp)
target_link_libraries(python_batch_bench PRIVATE impact_kernels)
target_include_directories(python_batch_bench PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
string(TOUPPER "${CMAKE_BUILD_TYPE}" IMPACT_PYTHON_BUILD_TYPE)
add_custom_target(benchmark_python
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${CMAKE_CURRENT_BINARY_DIR}/python ${Python3_EXECUTABLE}
          ${CMAKE_CURRENT_SOURCE_DIR}/tests/benchmarks/python_kernels.py $<TARGET_FILE:python_batch_bench>
          "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${IMPACT_PYTHON_BUILD_TYPE}} -ffp-contract=off"
  DEPENDS python python_batch_bench VERBATIM)
