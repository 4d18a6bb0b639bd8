# cmake -DPROGRAM=... -DNAME=... -DINCLUDE=... -DHELP2MAN=... -DOUT=dir/NAME.1.gz [-DDETAILS=ON] -P man_page.cmake
#
# A man page from the program itself (help2man reads --help and --version), plus
# the sections help2man cannot know (INCLUDE: exit status, files, examples). With
# DETAILS, every command's and subcommand's own --help is added as COMMANDS IN
# DETAIL, so the page lists every option of every command, as the program does.
cmake_minimum_required(VERSION 3.25)
set(work ${OUT}.work)
file(MAKE_DIRECTORY ${work})
file(READ ${INCLUDE} include_text)
# The defaults --help prints (the calibration file, the API socket) as a reader's
# ~ and $XDG_RUNTIME_DIR, not the build machine's paths; English.
set(as_reader ${CMAKE_COMMAND} -E env --unset=XDG_DATA_HOME --unset=LANGUAGE "HOME=~" "XDG_RUNTIME_DIR=$XDG_RUNTIME_DIR" LANG=C.UTF-8)

# Roff for a block of --help text shown as it is.
function(bp_roff_block text out_var)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

# The names in a "Commands:" or "Subcommands:" table of a --help text.
function(bp_command_names text heading out_var)
  set(names "")
  string(FIND "${text}" "${heading}:\n" at)
  if(at GREATER -1)
    string(SUBSTRING "${text}" ${at} -1 rest)
    # Only the names are wanted: a ';' in a summary must not split its line in two.
    string(REPLACE ";" "," rest "${rest}")
    string(REPLACE "\n" ";" lines "${rest}")
    list(REMOVE_AT lines 0)
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "^  ")
        break()
      endif()
      if(line MATCHES "^  ([a-z][a-z0-9-]*)  ")
        list(APPEND names ${CMAKE_MATCH_1})
      endif()
    endforeach()
  endif()
  set(${out_var} "${names}" PARENT_SCOPE)
endfunction()

function(bp_help out_var)
  execute_process(COMMAND ${as_reader} ${PROGRAM} ${ARGN} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} ${ARGN} --help failed: ${rc}")
  endif()
  set(${out_var} "${help}" PARENT_SCOPE)
endfunction()

if(DETAILS)
  bp_help(top)
  bp_command_names("${top}" "Commands" commands)
  if(NOT commands)
    message(FATAL_ERROR "${PROGRAM} --help lists no commands")
  endif()
  string(APPEND include_text "\n[COMMANDS IN DETAIL]\n")
  foreach(c IN LISTS commands)
    bp_help(help ${c})
    bp_roff_block("${help}" block)
    string(APPEND include_text ".SS \"${NAME} ${c}\"\n${block}")
    bp_command_names("${help}" "Subcommands" subs)
    foreach(s IN LISTS subs)
      bp_help(subhelp ${c} ${s})
      bp_roff_block("${subhelp}" block)
      string(APPEND include_text ".SS \"${NAME} ${c} ${s}\"\n${block}")
    endforeach()
  endforeach()
endif()

file(WRITE ${work}/${NAME}.h2m "${include_text}")
execute_process(COMMAND ${as_reader} ${HELP2MAN} --no-info --section=1 --include=${work}/${NAME}.h2m
                        --output=${work}/${NAME}.1 ${PROGRAM}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man ${PROGRAM}: ${err}")
endif()
# Compressed and without a time stamp, as Debian keeps man pages (reproducible).
execute_process(COMMAND gzip -9nf ${work}/${NAME}.1 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip ${NAME}.1 failed")
endif()
file(RENAME ${work}/${NAME}.1.gz ${OUT})
