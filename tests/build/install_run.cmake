# An installed copy finds what it ships through its install prefix, not through the
# source or build tree: `cmake --install` into a scratch prefix, then the installed
# programs run from a folder of their own (docs/install.md).
#   cmake -DBUILD=<build dir> -DWORK=<scratch dir> -DGUI=ON|OFF -DMAN=ON|OFF -P install_run.cmake
set(prefix "${WORK}/install-prefix")
set(away "${WORK}/install-elsewhere")
file(REMOVE_RECURSE "${prefix}" "${away}")
file(MAKE_DIRECTORY "${away}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${prefix}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${err}")
endif()

set(share "${prefix}/share")
set(expected bin/benchpilot-cli bin/benchpilot-sim
    share/benchpilot/examples/reagent-transfer.recipe.json share/benchpilot/examples/python/position_sweep.py
    share/benchpilot/labware/reservoir-12.labware.json share/benchpilot/machines/stage-grbl-uno.machine.json
    share/benchpilot/machines/analyzer.deck.json share/bash-completion/completions/benchpilot-cli
    share/doc/benchpilot/copyright lib/python3/dist-packages/benchpilot.py)
if(GUI)
  list(APPEND expected bin/benchpilot share/applications/io.github.benchpilot.BenchPilot.desktop
       share/metainfo/io.github.benchpilot.BenchPilot.metainfo.xml
       share/icons/hicolor/scalable/apps/io.github.benchpilot.BenchPilot.svg
       share/icons/hicolor/48x48/apps/io.github.benchpilot.BenchPilot.png)
endif()
if(MAN)
  list(APPEND expected share/man/man1/benchpilot-cli.1.gz share/man/man1/benchpilot-sim.1.gz)
endif()
foreach(f IN LISTS expected)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

function(run out_code out_text)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${away}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_code} "${rc}" PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()
set(cli "${prefix}/bin/benchpilot-cli")

run(rc text "${cli}" --version)
if(NOT rc EQUAL 0 OR NOT text MATCHES "^benchpilot-cli [0-9.]+\n.*GPL-3.0-or-later")
  message(FATAL_ERROR "installed benchpilot-cli --version: ${rc} ${text}")
endif()

# A recipe copied out of the examples names its labware by file name only; with no
# such file beside it, the installed program finds the one it ships.
file(COPY "${share}/benchpilot/examples/reagent-transfer.recipe.json" DESTINATION "${away}")
run(rc text "${cli}" recipe validate reagent-transfer.recipe.json)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed benchpilot-cli did not find the shipped labware (${rc}): ${text}")
endif()
run(rc text "${cli}" recipe validate "${share}/benchpilot/examples/sampling-96.recipe.json")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed example does not validate (${rc}): ${text}")
endif()
# A machine profile by its name: found (the port is what fails: link trouble, 3), not
# a usage error about --profile (1).
run(rc text "${cli}" --port "${away}/no-such-port" --profile stage-grbl-uno status)
if(NOT rc EQUAL 3 OR text MATCHES "--profile")
  message(FATAL_ERROR "the installed benchpilot-cli did not find the shipped profile (${rc}): ${text}")
endif()

# ...and it is the install prefix that answers: without its labware and machines the
# same commands fail.
file(RENAME "${share}/benchpilot/labware" "${share}/benchpilot/labware-away")
file(RENAME "${share}/benchpilot/machines" "${share}/benchpilot/machines-away")
run(rc_labware text_labware "${cli}" recipe validate reagent-transfer.recipe.json)
run(rc_profile text_profile "${cli}" --port "${away}/no-such-port" --profile stage-grbl-uno status)
if(rc_labware EQUAL 0 OR NOT rc_profile EQUAL 1)
  message(FATAL_ERROR "found without the prefix's share/benchpilot: labware ${rc_labware}, profile ${rc_profile}")
endif()
file(RENAME "${share}/benchpilot/labware-away" "${share}/benchpilot/labware")
file(RENAME "${share}/benchpilot/machines-away" "${share}/benchpilot/machines")

run(rc text "${prefix}/bin/benchpilot-sim" --version)
if(NOT rc EQUAL 0 OR NOT text MATCHES "^benchpilot-sim ")
  message(FATAL_ERROR "installed benchpilot-sim --version: ${rc} ${text}")
endif()
if(GUI)
  run(rc text "${CMAKE_COMMAND}" -E env QT_QPA_PLATFORM=offscreen "${prefix}/bin/benchpilot" --screenshot shot.png --screen jog
      --sim stage --settle-ms 50 --no-api)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${away}/shot.png")
    message(FATAL_ERROR "installed benchpilot --screenshot: ${rc} ${text}")
  endif()
endif()
file(REMOVE_RECURSE "${prefix}" "${away}")
message(STATUS "the installed programs found their files through ${prefix}")
