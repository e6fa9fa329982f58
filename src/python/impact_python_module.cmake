# impact_add_python_module: the kernels of one's own folder of derivation files as a Python
# package (docs/python.md), installed with Impact's CMake package (find_package(impact)).
#
#   impact_add_python_module(<package> DERIVATIONS <folder>)
#
# At build time runs `impact kernels --python` on <folder> into the build tree (the C++ kernel
# headers and, beside them, one binding source a derivation file), and builds with pybind11 the
# package <package> in ${CMAKE_CURRENT_BINARY_DIR}/<package>_python/<package>/: the module
# <package>._impact and the package's Python files, so that with
# PYTHONPATH=${CMAKE_CURRENT_BINARY_DIR}/<package>_python, `import <package>` gives each
# kernel of the folder as a function on NumPy arrays, as `impact` gives Impact's
# (`<package>.derive` derives with the installed `impact`). The target is <package>; the kernel
# headers are in its include path. Needs pybind11 (find_package(pybind11 CONFIG)) and Python 3
# with NumPy and its headers (find_package(Python3 COMPONENTS Interpreter Development.Module
# NumPy)), found by the caller or here. The list of derivation files is read when CMake
# configures: a file added needs a new configure.
function(impact_add_python_module package)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "DERIVATIONS" "")
  if(NOT arg_DERIVATIONS)
    message(FATAL_ERROR "impact_add_python_module(${package}): give DERIVATIONS <folder of derivation files>")
  endif()
  get_filename_component(folder "${arg_DERIVATIONS}" ABSOLUTE)
  file(GLOB files CONFIGURE_DEPENDS "${folder}/*.toml")
  if(NOT files)
    message(FATAL_ERROR "impact_add_python_module(${package}): ${folder} holds no derivation file (*.toml)")
  endif()
  if(NOT Python3_FOUND)
    find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module NumPy)
  endif()
  if(NOT pybind11_FOUND)
    find_package(pybind11 CONFIG REQUIRED)
  endif()
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/${package}_kernels)
  set(sources ${generated}/python/module.cpp)
  foreach(file IN LISTS files)
    get_filename_component(stem "${file}" NAME_WE)
    list(APPEND sources ${generated}/python/${stem}.cpp)
  endforeach()
  add_custom_command(
    OUTPUT ${sources}
    COMMAND ${IMPACT_EXECUTABLE} kernels --derivations ${folder} --output ${generated} --python --force --no-cache
    DEPENDS ${files} ${IMPACT_EXECUTABLE}
    COMMENT "impact kernels --python ${folder}"
    VERBATIM)
  set(package_dir ${CMAKE_CURRENT_BINARY_DIR}/${package}_python/${package})
  pybind11_add_module(${package} MODULE NO_EXTRAS ${IMPACT_PYTHON_SOURCE_DIR}/python/kernel_binding.cpp ${sources})
  target_include_directories(${package} PRIVATE ${generated}/kernels ${IMPACT_PYTHON_SOURCE_DIR})
  # The kernels as measured: without FMA contraction.
  target_compile_options(${package} PRIVATE $<$<OR:$<CXX_COMPILER_ID:GNU>,$<CXX_COMPILER_ID:Clang>>:-ffp-contract=off>)
  target_compile_features(${package} PRIVATE cxx_std_17)
  set_target_properties(${package} PROPERTIES OUTPUT_NAME _impact CXX_VISIBILITY_PRESET hidden
                                              LIBRARY_OUTPUT_DIRECTORY ${package_dir})
  file(MAKE_DIRECTORY ${package_dir})
  foreach(file __init__.py batch.py derivation.py)
    configure_file(${IMPACT_PYTHON_SOURCE_DIR}/python/impact/${file} ${package_dir}/${file} COPYONLY)
  endforeach()
  file(GENERATE OUTPUT ${package_dir}/_executable.py
       CONTENT "IMPACT_EXECUTABLE = \"${IMPACT_EXECUTABLE}\"\n")
endfunction()
