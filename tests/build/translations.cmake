# The translations are complete and up to date (docs/wording.md):
#  - lupdate run over the sources into copies of the .ts files changes nothing, so a
#    string added or changed in the code without `cmake --build build --target
#    update_translations` fails here (seconds: lupdate only, nothing is built);
#  - benchpilot_zh_CN.ts has no unfinished entry outside the contexts listed in
#    PENDING (empty: every context is translated).
# Called as: cmake -DSRC=<source dir> -DWORK=<scratch dir> -DLUPDATE=<lupdate> -P translations.cmake
cmake_minimum_required(VERSION 3.25)
set(TS_DIR ${SRC}/resources/translations)
file(REMOVE_RECURSE ${WORK}/ts)
file(MAKE_DIRECTORY ${WORK}/ts)
set(OPTIONS -locations none -no-obsolete -silent -I ${SRC})
foreach(ts benchpilot_zh_CN.ts benchpilot_en.ts)
  file(COPY ${TS_DIR}/${ts} DESTINATION ${WORK}/ts)
  set(extra)
  if(ts STREQUAL "benchpilot_en.ts")
    set(extra -pluralonly)
  endif()
  execute_process(COMMAND ${LUPDATE} ${OPTIONS} ${extra} ${SRC}/widgets ${SRC}/app ${SRC}/device -ts ${WORK}/ts/${ts}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "lupdate failed on ${ts}")
  endif()
  file(READ ${TS_DIR}/${ts} before)
  file(READ ${WORK}/ts/${ts} after)
  if(NOT before STREQUAL after)
    message(FATAL_ERROR "resources/translations/${ts} is out of date with the sources: run "
                        "`cmake --build build --target update_translations`, translate the new entries, commit")
  endif()
endforeach()

# Contexts still being translated: none (the screens, the accuracy bench, GRBL, the API
# and the CLI are all translated). A new context may be listed here while its words are
# in review; the list should stay short-lived.
set(PENDING)
file(READ ${TS_DIR}/benchpilot_zh_CN.ts zh)
# One list element per <context>: the text's own ';' (and brackets, which CMake
# treats as quoting inside a list) are set aside first.
string(REPLACE ";" "<semicolon>" zh "${zh}")
string(REPLACE "[" "<open>" zh "${zh}")
string(REPLACE "]" "<close>" zh "${zh}")
string(REPLACE "<context>" ";<context>" contexts "${zh}")
set(bad)
foreach(c IN LISTS contexts)
  string(REGEX MATCH "<name>([^<]*)</name>" _ "${c}")
  set(name ${CMAKE_MATCH_1})
  if(name STREQUAL "" OR name IN_LIST PENDING)
    continue()
  endif()
  string(REGEX MATCHALL "type=\"unfinished\"" unfinished "${c}")
  list(LENGTH unfinished n)
  if(n GREATER 0)
    list(APPEND bad "${name} (${n})")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "benchpilot_zh_CN.ts has unfinished entries: ${bad}")
endif()
message(STATUS "translations: up to date; zh_CN complete outside the pending screens")
