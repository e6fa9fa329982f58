# Installs Impact from BUILD into a scratch prefix, then configures and builds the project of
# tests/consumer_python against it on a folder holding one derivation file (DERIVATION), and
# imports the package it built with PYTHON: what a user of impact_add_python_module does.
set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/derivations)
file(COPY ${DERIVATION} DESTINATION ${WORK}/derivations)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix} OUTPUT_QUIET RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cmake --install failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK}/build -DCMAKE_PREFIX_PATH=${prefix}
                        -DDERIVATIONS=${WORK}/derivations -DPython3_EXECUTABLE=${PYTHON} -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the project does not configure against the installed package")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build -j2 RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the project does not build")
endif()
# Equal masses in an elastic collision exchange their velocities (typed here, not computed);
# and the package's derive runs the installed impact.
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${WORK}/build/my_kernels_python ${PYTHON} -c
  "import my_kernels as k; r = k.collide_line(2.0, 2.0, 3.0, -1.0, 1.0); assert (float(r.v_M), float(r.v_m)) == (-1.0, 3.0), r; assert k.status(int(r.status)).name == 'ok'; assert k.derive('${WORK}/derivations/eq08_inelastic_line.toml').results['J']; print(k.kernel_names)"
  RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the package built by impact_add_python_module does not give the folder's kernel")
endif()
message(STATUS "impact_add_python_module built a package for the folder's kernels, and it ran")
