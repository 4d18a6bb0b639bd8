# Warnings are errors in the project's own code; system headers (Qt, Eigen,
# QCustomPlot) come in through -isystem and are not held to this.
function(bp_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Woverloaded-virtual -Wcast-align -Werror)
endfunction()
