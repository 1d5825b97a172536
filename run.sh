#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine: installs the Debian packages the project needs
# (only the missing ones), configures and builds in Release, then runs the job asked for.
#   ./run.sh demo    build, then render the fighter demo (PNG frames, contact sheet, GIF, timing);
#                    further arguments go to `glideshadows demo` and override the defaults
#   ./run.sh play    build, then the fighter demo in a window (SDL2) with keys: H shows them
#   ./run.sh test    build, then run the whole test suite (ctest)
#   ./run.sh bench   build, then run the benchmark programs
#   ./run.sh sanitize [ctest args]  build in build-asan/ with ASan+UBSan (clang), then run the test
#                    suite there (all of it, or the ctest selection given, e.g. -L 'unit|numeric';
#                    SANITIZE_TARGETS builds only the targets named)
#   ./run.sh fuzz    build the libFuzzer targets in build-asan/ (the same build), run each for
#                    FUZZ_SECONDS (default 60; glide_api_fuzz FUZZ_API_SECONDS, default the same)
#                    from fuzz/corpus/, mutation seed FUZZ_SEED (default 1, so CI repeats
#                    itself); a finding fails the run
set -euo pipefail
cd "$(dirname "$0")"

usage() {
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'
}

PACKAGES=(
  cmake ninja-build g++ make pkg-config
  libosmesa6-dev libgl-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libglm-dev libopenimageio-dev openimageio-tools
  libgtest-dev libgmock-dev
  libcli11-dev nlohmann-json3-dev libtinyobjloader-dev libembree-dev
  clang libclang-rt-14-dev
  libsdl2-dev xvfb xauth xdotool x11-apps
  python3
)

install_missing_packages() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return
  fi
  echo "run.sh: installing ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null; then sudo=(sudo); else
      echo "run.sh: need root (or sudo) to install: ${missing[*]}" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Both builds use Ninja, which compiles a target's files while the libraries it links are still
# being built; Make waits for them, so on two cores one often idled: the sanitizer build of CI's
# targets took 151 s with Ninja against 258 s with Make (2013a5f, quiet machine). A build tree
# made by another generator is configured afresh (cmake refuses to switch generators in place).
configure_fresh_if_not_ninja() {
  if [ -f "$1/CMakeCache.txt" ] && ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$1/CMakeCache.txt"; then
    rm -rf "$1"
  fi
}

# Unity builds (CMAKE_UNITY_BUILD): each target's sources compiled in batches of 8, so the
# headers every file includes (GoogleTest, CLI11, GLM, nlohmann-json) are parsed and their inline
# code compiled once per batch, not once per file: the whole Release build took 469 s of CPU
# at 80075e0 against 830 s file by file at a4015e2. A name defined in two files of one target
# (even in an anonymous namespace) stops it with a "redefinition" error: give it a name of its
# own, or share one definition.
build() {
  install_missing_packages
  configure_fresh_if_not_ninja build
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON > build.log 2>&1 ||
    { cat build.log; exit 1; }
  cmake --build build -j"$(nproc)" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
  echo "run.sh: built in build/ (log: build.log)"
}

# The sanitizer build, shared by `sanitize` and `fuzz`: clang with -fsanitize=address,undefined
# (cmake/sanitizers.cmake) and libFuzzer's coverage on every library, so the sanitized test
# programs and the fuzz targets link the same objects and CI compiles the code once for both
# (GCC took 2.4 times as long to compile the same code with the sanitizers, measured per file).
# -O2 keeps the suite's run time; -g1 gives the reports file and line (full -g cost a third more
# compile time and adds nothing a report prints). A build-asan/ configured with another compiler
# (before this was clang) is configured afresh.
configure_sanitized() {
  install_missing_packages
  if [ -f build-asan/CMakeCache.txt ] &&
     ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++$' build-asan/CMakeCache.txt; then
    rm -rf build-asan
  fi
  configure_fresh_if_not_ninja build-asan
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_UNITY_BUILD=ON -DGLIDESHADOWS_FUZZ=ON \
    -DGLIDESHADOWS_BUILD_BENCH=OFF > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
}

# Builds the targets named (all of them when none is).
build_sanitized() {
  configure_sanitized
  local targets=()
  if [ $# -gt 0 ]; then targets=(--target "$@"); fi
  cmake --build build-asan -j"$(nproc)" "${targets[@]}" >> build-asan.log 2>&1 ||
    { tail -50 build-asan.log; exit 1; }
  echo "run.sh: built ${*:-everything} in build-asan/ (log: build-asan.log)"
}

# For every sanitized run: stop at the first report, with a stack; LeakSanitizer skips only the
# leaks cmake/lsan.supp names (inside Mesa and LLVM, which are not instrumented).
export_sanitizer_options() {
  # intercept_tls_get_addr=0: LeakSanitizer's stop-the-world tracer died with SIGSEGV at exit
  # after passing tests ("Tracer caught signal 11", 2 to 3 tests of ~580 in a CI run, a different
  # few each time). The cause is in the sanitizer runtime of GCC 12 (and LLVM up to 16): its
  # __tls_get_addr interceptor takes a dynamic TLS block whose address is 16 mod 4096 for a
  # glibc-2.19 block with a header, and reads a start and a size from the 16 bytes before it; on
  # glibc 2.25 and later those bytes are someone else's, and the tracer scans a range that is not
  # mapped (google/sanitizers#1322). The shim dlopens OSMesa or EGL, and with them the LLVM that
  # llvmpipe compiles shaders with; libLLVM's thread-locals use the general-dynamic model, so
  # their blocks are malloc'ed, and whether a test hits the bad case depends on where malloc put
  # one. With the interceptor off, LeakSanitizer does not scan dynamically allocated TLS blocks:
  # none of our code has a thread-local variable (grep finds none), so no leak of ours hides there.
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0}
  # No llvmpipe threads: with ctest -j2 on two cores llvmpipe's rasteriser threads only contend
  # with the other test process (the numeric suite takes 13% less time without them). Output
  # bytes do not depend on it, and Mesa is not instrumented anyway.
  export LP_NUM_THREADS=${LP_NUM_THREADS:-0}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
  # clang's runtime names a report's functions and lines with llvm-symbolizer, which Debian
  # installs (with clang) under /usr/lib/llvm-N/bin, not on the PATH.
  if [ -z "${ASAN_SYMBOLIZER_PATH:-}" ]; then
    local symbolizer
    symbolizer=$(command -v llvm-symbolizer || ls /usr/lib/llvm-*/bin/llvm-symbolizer 2>/dev/null | tail -1 || true)
    if [ -n "$symbolizer" ]; then export ASAN_SYMBOLIZER_PATH=$symbolizer; fi
  fi
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/cmake/lsan.supp:print_suppressions=0}
}

# The fuzz targets (fuzz/), in the sanitizer build: only they and what they link are built.
PARSER_FUZZ_TARGETS=(scene_file_fuzz obj_fuzz)
FUZZ_TARGETS=(glide_api_fuzz "${PARSER_FUZZ_TARGETS[@]}")

# Each target starts from the checked-in seeds (read only) and writes what it finds new to
# build-asan/fuzz-corpus/<target>/; a crashing input is saved in build-asan/fuzz-artifacts/.
# The mutation seed is fixed (FUZZ_SEED, default 1) so that CI explores the same inputs on
# every run; set another seed to explore further by hand. Returns non-zero on a finding.
fuzz_one() {
  local target=$1 time=$2
  shift 2
  mkdir -p "build-asan/fuzz-corpus/$target"
  echo "run.sh: fuzzing $target for ${time}s"
  if ! "build-asan/fuzz/$target" -seed="${FUZZ_SEED:-1}" -max_total_time="$time" -timeout=60 \
      -rss_limit_mb=4096 "$@" -print_final_stats=1 -artifact_prefix="build-asan/fuzz-artifacts/$target-" \
      "build-asan/fuzz-corpus/$target" "fuzz/corpus/$target" > "build-asan/$target.log" 2>&1; then
    echo "run.sh: $target found an input that fails (build-asan/$target.log):"
    tail -40 "build-asan/$target.log"
    return 1
  fi
  echo "run.sh: $target: $(grep -E '^stat::(number_of_executed_units|average_exec_per_sec)' \
    "build-asan/$target.log" | tr '\n' ' ')"
}

# Each fuzzer is one single-threaded process (llvmpipe has no threads here), so on a machine
# with two cores the API fuzzer runs on one while the two parser fuzzers take turns on the
# other: the run takes the API fuzzer's time, not the sum, and each fuzzer still gets a core.
run_fuzzers() {
  local seconds=${FUZZ_SECONDS:-60}
  local failed=()
  export_sanitizer_options
  mkdir -p build-asan/fuzz-artifacts
  # No leak check after each input (the sanitized test suite checks the shim's leaks): the GL
  # stack keeps what an input compiled (shaders, by design, for the next inputs), so nearly
  # every input looked like a possible leak and libFuzzer stopped the world to scan the whole
  # heap after it, a third of the run's time. Mesa's shader cache (in build-asan/, never in the
  # home directory) spares an input with a window of its own size recompiling what the run
  # already compiled.
  MESA_SHADER_CACHE_DISABLE=false MESA_SHADER_CACHE_DIR="$PWD/build-asan/fuzz-shader-cache" \
    fuzz_one glide_api_fuzz "${FUZZ_API_SECONDS:-$seconds}" -detect_leaks=0 &
  local api_fuzzer=$!
  for target in "${PARSER_FUZZ_TARGETS[@]}"; do
    fuzz_one "$target" "$seconds" || failed+=("$target")
  done
  wait "$api_fuzzer" || failed+=(glide_api_fuzz)
  if [ ${#failed[@]} -gt 0 ]; then
    echo "run.sh: findings in ${failed[*]} (inputs in build-asan/fuzz-artifacts/, logs in build-asan/)" >&2
    exit 1
  fi
  echo "run.sh: ${#FUZZ_TARGETS[@]} fuzz targets ran without a finding"
}

# Mesa's shader cache would otherwise write to ~/.cache; it changes no pixel.
export MESA_SHADER_CACHE_DISABLE=${MESA_SHADER_CACHE_DISABLE:-true}

# `./run.sh demo`'s arguments to `glideshadows demo` (one 8 s fight loop); the user's come after
# them and win, as the demo takes an option's last value (tests/demo reads this line).
DEMO_DEFAULTS=(--frames 96 --fps 12 --out out/demo --contact-sheet --gif)

case "${1:-}" in
  demo)
    build
    shift
    ./build/glideshadows demo "${DEMO_DEFAULTS[@]}" "$@"
    ;;
  play)
    build
    shift
    ./build/glideshadows demo --window "$@"
    ;;
  test)
    build
    # The tests keep Mesa's shader cache in the build tree (tests/CMakeLists.txt).
    MESA_SHADER_CACHE_DISABLE=false ctest --test-dir build --output-on-failure -j2
    ;;
  sanitize)
    # SANITIZE_TARGETS (words) names the targets to build; all of them when unset.
    read -r -d '' -a sanitize_targets <<< "${SANITIZE_TARGETS:-}" || true
    build_sanitized "${sanitize_targets[@]}"
    export_sanitizer_options
    shift
    # Every test runs once: a failure is a failure (no retry; see intercept_tls_get_addr above).
    MESA_SHADER_CACHE_DISABLE=false ctest --test-dir build-asan --output-on-failure -j2 "$@"
    ;;
  fuzz)
    build_sanitized "${FUZZ_TARGETS[@]}"
    run_fuzzers
    ;;
  bench)
    build
    ./build/bench/shim_bench
    ./build/bench/demo_bench
    ;;
  -h|--help|help)
    usage
    ;;
  *)
    usage >&2
    exit 2
    ;;
esac
