# test_web (docs/web.md): the web report read in headless Chromium. The paper's pages
# (output/html, which test_cli_output proves current) and a folder of one's own
# (tests/examples, regenerated here) are opened and checked by check_pages.py; the checker is
# first shown to report each fault put in a page on purpose; a picture of one derivation page
# is taken (web_inelastic_line.png in the build tree, docs/web_inelastic_line.png its copy).
# Arguments: IMPACT (the command), PYTHON, SOURCE (the project), WORK (a scratch folder).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${PYTHON} ${SOURCE}/tests/web/check_pages.py --self-test ${SOURCE}/output/html/energy_loss.html
                RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "check_pages.py does not report the faults put in a page")
endif()
execute_process(COMMAND ${IMPACT} regenerate --derivations ${SOURCE}/tests/examples --output ${WORK}/examples
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the examples' folder does not regenerate")
endif()
# Every check's proof typeset in its <details>; the verification summaries against their
# derivations.json. The addresses docs/web.md promises, typed here: a derivation's given equation, result, check
# and kernel output, a figure, rows of the errata, and in the folder of one's own a kernel's
# output and a check.
set(html ${SOURCE}/output/html)
execute_process(COMMAND ${PYTHON} ${SOURCE}/tests/web/check_pages.py
                        --screenshot ${html}/inelastic_line.html ${WORK}/web_inelastic_line.png
                        --expect ${html}/inelastic_line.html\#impulse_M
                        --expect ${html}/inelastic_line.html\#result-v_M_after
                        --expect ${html}/inelastic_line.html\#check-momentum_conserved
                        --expect ${html}/inelastic_line.html\#kernel-collide_line-J
                        --expect ${html}/inelastic_line.html\#kernel-collide_line-fixed-M
                        --expect ${html}/index.html\#errata
                        --expect ${html}/index.html\#verification
                        --expect ${html}/index.html\#fig-billiard
                        --expect ${html}/index.html\#errata-eq-12-third-line
                        --expect ${html}/index.html\#errata-eq-14-first-line-2
                        --expect ${WORK}/examples/html/pushed_puck.html\#kernel-push
                        --summary ${html}/index.html ${SOURCE}/output/derivations.json
                        --summary ${WORK}/examples/html/index.html ${WORK}/examples/derivations.json
                        ${html} ${WORK}/examples/html
                RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the web pages do not read well in Chromium (above)")
endif()
