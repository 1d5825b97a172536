# Builds every target of the project with AddressSanitizer and UndefinedBehaviorSanitizer
# (GLIDESHADOWS_SANITIZE=ON) and, for clang, adds the libFuzzer flags the fuzz targets need
# (GLIDESHADOWS_FUZZ=ON). Mesa and LLVM are not instrumented; their leaks are suppressed by
# name in cmake/lsan.supp (see there why), never for our own code. -g1 (line tables) is what a
# report's stack needs: file, line and function.
option(GLIDESHADOWS_SANITIZE "Build everything with -fsanitize=address,undefined" OFF)
option(GLIDESHADOWS_FUZZ "Build the libFuzzer targets in fuzz/ (clang only; implies SANITIZE)" OFF)

if(GLIDESHADOWS_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "GLIDESHADOWS_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif()
  set(GLIDESHADOWS_SANITIZE ON CACHE BOOL "" FORCE)
endif()

if(GLIDESHADOWS_SANITIZE)
  set(GLIDESHADOWS_SANITIZER_FLAGS
    -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g1)
  add_compile_options(${GLIDESHADOWS_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
  if(CMAKE_C_COMPILER_ID MATCHES "Clang")
    # A C program linking the C++ library needs UBSan's C++ half (the vptr checks' runtime),
    # which clang links only into C++ programs unless asked, and libstdc++ for its type info.
    add_link_options("$<$<LINK_LANGUAGE:C>:-fsanitize-link-c++-runtime;-lstdc++>")
  endif()
  # The options the runs need (stop at the first report, suppress only the uninstrumented
  # Mesa/LLVM stack's leaks) are exported by run.sh (`sanitize`, `fuzz`) before ctest or the
  # fuzzers start, so that a test program run by hand in build-asan/ gets them the same way.
endif()

# libFuzzer's coverage feedback, for the code a fuzz target links: the shim and the rooms of
# src/ (glideshadows_fuzz_coverage, called on each); the fuzz targets add -fsanitize=fuzzer.
function(glideshadows_fuzz_coverage target)
  if(GLIDESHADOWS_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# The command-line tool and the demo (glideshadows_driver_code, called on each): in the
# sanitizer build they only drive the code the tests aim at, and are compiled at -O0. Every
# check is the same (the sanitizers instrument each load, store and operation at any level),
# the compile takes well under half the time (CLI11's templates are most of it), and what the
# programs spend their time in (the shim, the techniques, llvmpipe) stays at -O2. Other builds
# keep their flags: these are the programs people run. (The test programs are -O0 in every
# build: tests/CMakeLists.txt.)
function(glideshadows_driver_code target)
  if(GLIDESHADOWS_SANITIZE)
    target_compile_options(${target} PRIVATE -O0)
  endif()
endfunction()
