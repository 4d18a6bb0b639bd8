# cmake -DPROGRAM=... -DARGS="a;b" -DOUT=file -P run_to_file.cmake
# Runs a program and keeps what it prints (the bash completion is made this way
# from the program it completes, so the two cannot drift).
execute_process(COMMAND ${PROGRAM} ${ARGS} OUTPUT_FILE ${OUT}.tmp RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(REMOVE ${OUT}.tmp)
  message(FATAL_ERROR "${PROGRAM} ${ARGS} failed: ${rc}")
endif()
file(RENAME ${OUT}.tmp ${OUT})
