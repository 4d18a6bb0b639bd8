# What `cmake --install` (and so the Debian package, cmake/package.cmake) puts where
# (docs/install.md):
#   bin/                                   benchpilot, benchpilot-cli, benchpilot-sim
#   share/benchpilot/examples/             resources/examples/ and the Python client's examples
#   share/benchpilot/labware/              the labware definitions among the examples
#   share/benchpilot/machines/             machine profiles and the analyzer's deck
#   share/bash-completion/completions/     benchpilot-cli's completion, made by the program
#   share/man/man1/                        the three man pages, made by help2man from --help
#   share/applications/, share/metainfo/, share/icons/hicolor/   the desktop entry
#   share/doc/benchpilot/                  the licence (as Debian's copyright file), the guides
#   lib/python3/dist-packages/             the Python client (where Debian's python3 looks)
# The programs find share/benchpilot/ from their own folder (BP_DATA_FROM_BIN); the
# build tree gets the same folder, linked into resources/, so it works as installed.
set(BP_ID io.github.benchpilot.BenchPilot)
set(BP_RES ${PROJECT_SOURCE_DIR}/resources)

file(GLOB BP_EXAMPLE_FILES CONFIGURE_DEPENDS ${BP_RES}/examples/*)
file(GLOB BP_LABWARE_FILES CONFIGURE_DEPENDS ${BP_RES}/examples/*.labware.json ${BP_RES}/examples/*.opentrons-labware.json)
file(GLOB BP_MACHINE_FILES CONFIGURE_DEPENDS ${BP_RES}/examples/*.machine.json ${BP_RES}/machines/*.json)
file(GLOB BP_PYTHON_EXAMPLES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/clients/python/examples/*.py)

# The build tree's share/benchpilot/, where the programs in app/ look.
get_filename_component(bp_build_data "${PROJECT_BINARY_DIR}/app/${BP_DATA_FROM_BIN}" ABSOLUTE)
file(REMOVE_RECURSE ${bp_build_data}/examples ${bp_build_data}/labware ${bp_build_data}/machines)
file(MAKE_DIRECTORY ${bp_build_data}/labware ${bp_build_data}/machines)
file(CREATE_LINK ${BP_RES}/examples ${bp_build_data}/examples SYMBOLIC)
foreach(kind labware machine)
  set(dir ${kind})
  if(kind STREQUAL "machine")
    set(dir machines)
  endif()
  string(TOUPPER ${kind} upper)
  foreach(f IN LISTS BP_${upper}_FILES)
    get_filename_component(name ${f} NAME)
    file(CREATE_LINK ${f} ${bp_build_data}/${dir}/${name} SYMBOLIC)
  endforeach()
endforeach()

foreach(program benchpilot benchpilot-cli benchpilot-sim)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

install(FILES ${BP_EXAMPLE_FILES} DESTINATION ${BP_INSTALL_DATADIR}/examples)
install(FILES ${BP_PYTHON_EXAMPLES} DESTINATION ${BP_INSTALL_DATADIR}/examples/python)
install(FILES ${BP_LABWARE_FILES} DESTINATION ${BP_INSTALL_DATADIR}/labware)
install(FILES ${BP_MACHINE_FILES} DESTINATION ${BP_INSTALL_DATADIR}/machines)
set(BP_INSTALL_PYTHONDIR "lib/python3/dist-packages" CACHE PATH "Where the Python client goes, under the prefix")
install(FILES ${PROJECT_SOURCE_DIR}/clients/python/benchpilot.py DESTINATION ${BP_INSTALL_PYTHONDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} RENAME copyright)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/README.zh_CN.md ${PROJECT_SOURCE_DIR}/docs/install.md
              ${PROJECT_SOURCE_DIR}/docs/licences.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

if(TARGET benchpilot)
  install(FILES ${BP_RES}/desktop/${BP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES ${BP_RES}/desktop/${BP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
  install(FILES ${BP_RES}/icons/benchpilot.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps RENAME ${BP_ID}.svg)
  foreach(size 16 32 48 64 128 256)
    install(FILES ${BP_RES}/icons/hicolor/${size}x${size}/benchpilot.png
            DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps RENAME ${BP_ID}.png)
  endforeach()
endif()

# Made from the programs at build time, so they say what the programs do.
set(bp_generated ${PROJECT_BINARY_DIR}/generated)
if(TARGET benchpilot-cli)
  add_custom_command(OUTPUT ${bp_generated}/completion/benchpilot-cli
    COMMAND ${CMAKE_COMMAND} -E make_directory ${bp_generated}/completion
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:benchpilot-cli> "-DARGS=completion$<SEMICOLON>bash"
            -DOUT=${bp_generated}/completion/benchpilot-cli -P ${PROJECT_SOURCE_DIR}/cmake/run_to_file.cmake
    DEPENDS benchpilot-cli ${PROJECT_SOURCE_DIR}/cmake/run_to_file.cmake
    COMMENT "bash completion from benchpilot-cli completion bash" VERBATIM)
  add_custom_target(bp_completion ALL DEPENDS ${bp_generated}/completion/benchpilot-cli)
  install(FILES ${bp_generated}/completion/benchpilot-cli DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
endif()

find_program(BP_HELP2MAN help2man)
set(BP_HAVE_MAN OFF)
if(BP_HELP2MAN)
  set(BP_HAVE_MAN ON)
  set(BP_DATADIR ${CMAKE_INSTALL_FULLDATADIR}/benchpilot)
  set(BP_DOCDIR ${CMAKE_INSTALL_FULLDOCDIR})
  set(bp_pages "")
  foreach(program benchpilot benchpilot-cli benchpilot-sim)
    if(NOT TARGET ${program})
      continue()
    endif()
    configure_file(${BP_RES}/man/${program}.h2m.in ${bp_generated}/man/${program}.h2m @ONLY)
    set(details OFF)
    if(program STREQUAL "benchpilot-cli")
      set(details ON)
    endif()
    set(page ${bp_generated}/man/${program}.1.gz)
    add_custom_command(OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${program}> -DNAME=${program} -DINCLUDE=${bp_generated}/man/${program}.h2m
              -DHELP2MAN=${BP_HELP2MAN} -DOUT=${page} -DDETAILS=${details} -P ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
      DEPENDS ${program} ${bp_generated}/man/${program}.h2m ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
      COMMENT "man page ${program}.1 (help2man)" VERBATIM)
    list(APPEND bp_pages ${page})
  endforeach()
  add_custom_target(bp_man ALL DEPENDS ${bp_pages})
  install(FILES ${bp_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man pages (./scripts/setup installs it)")
endif()

# What an install needs built, and no test: ./scripts/package builds this.
add_custom_target(bp_installable)
foreach(t benchpilot benchpilot-cli benchpilot-sim bp_completion bp_man)
  if(TARGET ${t})
    add_dependencies(bp_installable ${t})
  endif()
endforeach()
