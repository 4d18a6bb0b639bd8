# Our own code is held to these warnings; system headers (Qt, Eigen, QCustomPlot)
# come in through -isystem and are not. Warnings become errors only for us
# (BP_WERROR, on in ./scripts/test and CI): a packager or user building with
# another compiler or optimization level must not be stopped by a new warning.
option(BP_WERROR "Treat warnings in BenchPilot's own code as errors (developers, CI)" OFF)

function(bp_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Woverloaded-virtual -Wcast-align)
  if(BP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
