# CANDELA_FUZZ=ON: every target is built with AddressSanitizer, UndefinedBehaviorSanitizer and
# libFuzzer's coverage instrumentation, and fuzz/ adds the fuzz targets. Meant for a build folder
# of its own (scripts/fuzz uses build-fuzz); the normal build is untouched while it is OFF.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "CANDELA_FUZZ=ON needs clang (libFuzzer), not ${CMAKE_CXX_COMPILER_ID}: "
                      "configure with -DCMAKE_CXX_COMPILER=clang++")
endif()
if(NOT CANDELA_CUDA STREQUAL "OFF")
  message(FATAL_ERROR "CANDELA_FUZZ=ON builds the CPU code only: add -DCANDELA_CUDA=OFF")
endif()
set(CANDELA_SANITIZERS -fsanitize=address,undefined -fno-sanitize-recover=all)
add_compile_options(${CANDELA_SANITIZERS} -fsanitize=fuzzer-no-link -fno-omit-frame-pointer -g)
add_link_options(${CANDELA_SANITIZERS})
