# Coverage-guided fuzzing (docs/testing.md, "Fuzzing"): with BP_LIBFUZZER the drivers
# under tests/fuzz/ build as libFuzzer targets, and every library they link is
# compiled with the fuzzer's coverage instrumentation and ASan + UBSan, so libFuzzer
# sees the edges of the readers it feeds, not only those of the driver. Clang only:
#   CC=clang CXX=clang++ cmake -S . -B build-libfuzzer -G Ninja -DBP_LIBFUZZER=ON \
#     -DBP_WITH_WIDGETS=OFF -DBP_WITH_BENCH=OFF -DBP_UNITY=ON \
#     -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only"
#   cmake --build build-libfuzzer --target fuzz_codec fuzz_files fuzz_api
# The tree is for fuzzing only: its fuzz programs take libFuzzer's flags, not the
# drivers' --iterations, so CTest runs none of them there.
option(BP_LIBFUZZER "Build tests/fuzz's drivers as libFuzzer targets (clang; docs/testing.md)" OFF)
if(BP_LIBFUZZER)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "BP_LIBFUZZER needs clang (CXX=clang++), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  if(BP_SANITIZE)
    message(FATAL_ERROR "BP_LIBFUZZER brings its own sanitizers; leave BP_SANITIZE off")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# A fuzz driver's program: libFuzzer's main() and LLVMFuzzerTestOneInput under
# BP_LIBFUZZER, the deterministic driver (its own main()) otherwise.
function(bp_fuzz_driver target)
  if(BP_LIBFUZZER)
    target_compile_definitions(${target} PRIVATE BP_LIBFUZZER)
    target_link_options(${target} PRIVATE -fsanitize=fuzzer)
  endif()
endfunction()
