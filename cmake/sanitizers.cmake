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
  # fuzzers start; ctest's ENVIRONMENT cannot carry them through gtest_discover_tests, which
  # splits a list property.
endif()

if(GLIDESHADOWS_FUZZ)
  # Coverage feedback from every library; the fuzz targets add -fsanitize=fuzzer when linking.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
