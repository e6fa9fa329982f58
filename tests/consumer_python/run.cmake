# Installs Impact from BUILD into a scratch prefix, then configures and builds the project of
# tests/consumer_python against it on a folder holding one derivation file (DERIVATION), and
# imports the package it built with PYTHON: what a user of impact_add_python_module does.
set(prefix ${WORK}/prefix)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/derivations)
# The file without its batch loop: a folder's kernel bound through the scalar kernel's loop,
# which no kernel of the project's own takes (each has a batch loop or returns one value).
file(READ ${DERIVATION} text)
string(REPLACE "\nbatch = true\n" "\n" text "${text}")
get_filename_component(name ${DERIVATION} NAME)
file(WRITE ${WORK}/derivations/${name} "${text}")
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
# Equal masses in an elastic collision exchange their velocities, and J = 2 * 2 * 4 / 2 = 8
# (typed here, not computed); a separating pair is refused, its velocities kept and J = 0;
# the package's derive runs the installed impact; and the pair again in place on the package's
# batch_arrays (through the scalar kernel's loop, as this folder's kernel has no batch).
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${WORK}/build/my_kernels_python ${PYTHON} -c
  "import my_kernels as k; r = k.collide_line([2.0, 2.0], 2.0, [3.0, -1.0], -1.0, 1.0); assert (list(r.v_M), list(r.v_m), list(r.J)) == ([-1.0, -1.0], [3.0, -1.0], [8.0, 0.0]), r; assert [k.status(int(s)).name for s in r.status] == ['ok', 'separating']; assert k.derive('${WORK}/derivations/eq08_inelastic_line.toml').results['J']; b = k.batch_arrays(k.collide_line, 1); b.M[:], b.m[:], b.v_M[:], b.v_m[:], b.eps[:] = 2.0, 2.0, 3.0, -1.0, 1.0; r = k.collide_line(*b.inputs, out=b.out); assert r.v_M is b.v_M and (b.v_M[0], b.v_m[0], b.J[0]) == (-1.0, 3.0, 8.0), r; print(k.kernel_names)"
  RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the package built by impact_add_python_module does not give the folder's kernel")
endif()
message(STATUS "impact_add_python_module built a package for the folder's kernels, and it ran")
