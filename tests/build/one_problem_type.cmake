# One problem type and one result shape (motion/problem.h, motion/checked.h): a new
# `struct SomethingProblem` or a second "value or the problems why not" template is
# refused here, so the next area reuses them instead of copying them.
#   cmake -DSRC=<source dir> -P one_problem_type.cmake
#
# Allowed beside them, each for a reason:
#   GainProblem   motion/control/gains.h: a gain's refusal as the reference firmware
#                 words it on the wire (index, value, limit), not a validator's report
#   ParamProblem  app/api/command_methods.h: a JSON-RPC parameter already worded for
#                 the API's error reply
set(allowed_problems "GainProblem;ParamProblem")
# Readers that still return a struct of their own (some carry more than the value: the
# parsed document, whether the form was exact); this list only shrinks.
set(allowed_results "LimitsRead;AccuracyResultRead;RunLogRead;AccuracyTestRead;LinuxcncRead;CompensationRead;ErrorCurveRead;SequenceRead;ReadingsRead;MachineProfileReadResult;PatternReadResult;CalibrationRead;DeckRead;LabwareRead;RecipeRead;PlanReadResult;RunLogReadResult;TuningRead;ParseResult")

file(GLOB_RECURSE sources RELATIVE "${SRC}"
     "${SRC}/app/*.h" "${SRC}/app/*.cpp" "${SRC}/device/*.h" "${SRC}/device/*.cpp"
     "${SRC}/motion/*.h" "${SRC}/motion/*.cpp" "${SRC}/widgets/*.h" "${SRC}/widgets/*.cpp"
     "${SRC}/imaging/*.h" "${SRC}/imaging/*.cpp")
set(bad "")
foreach(f IN LISTS sources)
  if(f STREQUAL "motion/problem.h" OR f STREQUAL "motion/checked.h")
    continue()
  endif()
  file(STRINGS "${SRC}/${f}" lines REGEX "(struct|class) +[A-Za-z0-9_]*(Problem|ReadResult|ParseResult|Read|Expected|Checked) *({|:[^:]|$)")
  foreach(l IN LISTS lines)
    if(l MATCHES "(struct|class) +([A-Za-z0-9_]*(Problem|ReadResult|ParseResult|Read|Expected|Checked))")
      set(name "${CMAKE_MATCH_2}")
      if(name MATCHES "Problem$")
        list(FIND allowed_problems "${name}" known)
        if(known EQUAL -1)
          string(APPEND bad "  ${f}: ${name}: a problem is a motion::msg::Problem (motion/problem.h)\n")
        endif()
      else()
        list(FIND allowed_results "${name}" known)
        if(known EQUAL -1)
          string(APPEND bad "  ${f}: ${name}: a value or the problems why not is a motion::msg::Checked<T> (motion/checked.h)\n")
        endif()
      endif()
    endif()
  endforeach()
  # A template that pairs a value with its refusal is a second Checked.
  file(READ "${SRC}/${f}" text)
  if(text MATCHES "template *<[^>]*>[ \n]*(struct|class) +([A-Za-z0-9_]+)[ \n]*{[^}]*std::optional<")
    string(APPEND bad "  ${f}: ${CMAKE_MATCH_2}: a value or the problems why not is a motion::msg::Checked<T> (motion/checked.h)\n")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "a second problem or result type:\n${bad}")
endif()
message(STATUS "one problem type, one result shape")
